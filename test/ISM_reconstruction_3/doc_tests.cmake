# Tests of the documentation (included from test/ISM_reconstruction_3/CMakeLists.txt):
# - doc_check_defaults: every default documented in the reference manual (the
#   \cgalParamDefault of the named parameters) and in the user manual's parameter table
#   equals the code's (struct Settings in internal/settings.h);
# - doc_build: the HTML documentation builds with doxygen without a single warning
#   (registered only when doxygen is found; its output goes to the build tree).
get_filename_component(ISM_DOC_ROOT "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)

find_program(ISM_PYTHON3_EXECUTABLE NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT ISM_PYTHON3_EXECUTABLE)
  find_program(ISM_PYTHON3_EXECUTABLE python3)
endif()
if(ISM_PYTHON3_EXECUTABLE)
  add_test(NAME doc_check_defaults
           COMMAND ${ISM_PYTHON3_EXECUTABLE} ${ISM_DOC_ROOT}/doc/ISM_reconstruction_3/check_defaults.py
                   ${ISM_DOC_ROOT})
else()
  message(STATUS "python3 not found: test doc_check_defaults is not registered")
endif()

find_program(DOXYGEN_EXECUTABLE doxygen)
if(DOXYGEN_EXECUTABLE)
  add_test(NAME doc_build
           COMMAND ${CMAKE_COMMAND} -E env DOXYGEN=${DOXYGEN_EXECUTABLE}
                   bash ${ISM_DOC_ROOT}/scripts/build_doc.sh ${CMAKE_CURRENT_BINARY_DIR}/doc)
  set_tests_properties(doc_build PROPERTIES TIMEOUT 600)
else()
  message(STATUS "doxygen not found (apt-get install -y doxygen graphviz): test doc_build is not registered")
endif()
