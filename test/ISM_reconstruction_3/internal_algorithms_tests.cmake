# Unit tests of the internal algorithms on flat arrays (Ising annealing, marching
# tetrahedra, Taubin smoothing). Included by test/ISM_reconstruction_3/CMakeLists.txt.
add_executable(test_internal_algorithms ${CMAKE_CURRENT_LIST_DIR}/test_internal_algorithms.cpp)
target_link_libraries(test_internal_algorithms PRIVATE ISM_reconstruction_3)
add_test(NAME internal_algorithms COMMAND test_internal_algorithms)
