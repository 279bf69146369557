# cmake --install puts the headers and a package config in place, so that an
# outside project does find_package(ISM_reconstruction_3) and links
# ISM_reconstruction_3::ISM_reconstruction_3, which brings CGAL, Eigen and TBB.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
install(DIRECTORY include/CGAL DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT Devel)
install(TARGETS ISM_reconstruction_3 EXPORT ISM_reconstruction_3Targets COMPONENT Devel)
set(ISM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ISM_reconstruction_3)
install(EXPORT ISM_reconstruction_3Targets NAMESPACE ISM_reconstruction_3::
        DESTINATION ${ISM_CMAKE_DIR} COMPONENT Devel)
configure_package_config_file(cmake/ISM_reconstruction_3Config.cmake.in
  "${CMAKE_CURRENT_BINARY_DIR}/ISM_reconstruction_3Config.cmake"
  INSTALL_DESTINATION ${ISM_CMAKE_DIR})
write_basic_package_version_file(
  "${CMAKE_CURRENT_BINARY_DIR}/ISM_reconstruction_3ConfigVersion.cmake"
  COMPATIBILITY SameMajorVersion ARCH_INDEPENDENT)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/ISM_reconstruction_3Config.cmake"
              "${CMAKE_CURRENT_BINARY_DIR}/ISM_reconstruction_3ConfigVersion.cmake"
        DESTINATION ${ISM_CMAKE_DIR} COMPONENT Devel)
