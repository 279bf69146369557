# Tests of the tet-mesh writers (CGAL/ISM_reconstruction_3/IO/tet_mesh_io.h).
# include()d from test/ISM_reconstruction_3/CMakeLists.txt; needs the ISM_reconstruction_3 target.

add_executable(test_tet_mesh_io ${CMAKE_CURRENT_LIST_DIR}/test_tet_mesh_io.cpp)
target_link_libraries(test_tet_mesh_io PRIVATE ISM_reconstruction_3)

set(ISM_TET_MESH_IO_OUT ${CMAKE_CURRENT_BINARY_DIR}/tet_mesh_io_out)
add_test(NAME test_tet_mesh_io COMMAND test_tet_mesh_io ${ISM_TET_MESH_IO_OUT})
set_tests_properties(test_tet_mesh_io PROPERTIES FIXTURES_SETUP ism_tet_mesh_io_files)

# Debian's python3-vtk9 only loads with the system interpreter, hence the fixed path.
add_test(NAME test_tet_mesh_io_check_vtu
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/check_vtu.py
                 ${ISM_TET_MESH_IO_OUT}/cube_expected.json
                 ${ISM_TET_MESH_IO_OUT}/cube.vtu
                 ${ISM_TET_MESH_IO_OUT}/cube_ascii.vtu)
set_tests_properties(test_tet_mesh_io_check_vtu PROPERTIES FIXTURES_REQUIRED ism_tet_mesh_io_files)
