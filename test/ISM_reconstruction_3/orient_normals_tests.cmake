# Tests of CGAL::ism_orient_normals() against mst_orient_normals() on sampled meshes.
# Included from test/ISM_reconstruction_3/CMakeLists.txt; needs the ISM_reconstruction_3
# interface target and ISM_DATA_DIR (meshes extracted at configure time).
add_executable(test_orient_normals ${CMAKE_CURRENT_SOURCE_DIR}/test_orient_normals.cpp)
target_include_directories(test_orient_normals PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/common)
target_link_libraries(test_orient_normals PRIVATE ISM_reconstruction_3)
add_test(NAME orient_normals COMMAND test_orient_normals ${ISM_DATA_DIR}/meshes)
