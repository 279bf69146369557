# ism_orient_normals() feeding CGAL's Poisson reconstruction. Included from
# examples/ISM_reconstruction_3/CMakeLists.txt (needs the ISM_reconstruction_3 interface
# target and ISM_DATA_DIR, where CGAL::data_file_path() finds meshes/bunny00.off).
add_executable(ism_orient_normals_poisson_example
               ${CMAKE_CURRENT_LIST_DIR}/ism_orient_normals_poisson_example.cpp)
target_link_libraries(ism_orient_normals_poisson_example PRIVATE ISM_reconstruction_3)
target_compile_definitions(ism_orient_normals_poisson_example PRIVATE CGAL_DATA_DIR="${ISM_DATA_DIR}")
