# cmake --install into a scratch prefix, then configure, build and run an outside project
# that does find_package(ISM_reconstruction_3).
set(ISM_INSTALL_TEST_DIR ${CMAKE_BINARY_DIR}/install_test)
add_test(NAME install_and_consume
  COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${CMAKE_BINARY_DIR} -DWORK_DIR=${ISM_INSTALL_TEST_DIR}
          -DCONSUMER_DIR=${CMAKE_CURRENT_LIST_DIR}/install_consumer
          -P ${CMAKE_CURRENT_LIST_DIR}/install_consumer/run_install_test.cmake)
