add_executable(test_reconstruction ${CMAKE_CURRENT_LIST_DIR}/test_reconstruction.cpp)
target_include_directories(test_reconstruction PRIVATE ${CMAKE_CURRENT_LIST_DIR}/common)
target_link_libraries(test_reconstruction PRIVATE ISM_reconstruction_3)
add_test(NAME reconstruction COMMAND test_reconstruction ${ISM_DATA_DIR}/meshes)
