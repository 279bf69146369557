# Tests of the evaluation utilities (common/ism_evaluation.h) shared by tests and benchmarks.
# Included from test/ISM_reconstruction_3/CMakeLists.txt; needs the ISM_reconstruction_3
# interface target and ISM_DATA_DIR (meshes extracted at configure time).
add_executable(test_evaluation ${CMAKE_CURRENT_SOURCE_DIR}/test_evaluation.cpp)
target_include_directories(test_evaluation PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/common)
target_link_libraries(test_evaluation PRIVATE ISM_reconstruction_3)
add_test(NAME evaluation COMMAND test_evaluation ${ISM_DATA_DIR}/meshes)
