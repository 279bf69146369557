# End-to-end tests of the command-line tool ism_reconstruct and smoke runs of the examples.
# include()d from test/ISM_reconstruction_3/CMakeLists.txt. The tool and the examples are
# targets of examples/ISM_reconstruction_3 (option ISM_BUILD_EXAMPLES, on by default),
# which the top level adds before the tests; without them nothing is registered here.

if(TARGET ism_reconstruct AND TARGET sample_mesh_points)
  # test_tool.sh: success on 5,000 sphere points (closed, genus 0); bad input files give
  # exit 1 and leave no output; usage errors give exit 2; --help lists every option.
  add_test(NAME tool
           COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/test_tool.sh
                   $<TARGET_FILE:ism_reconstruct> $<TARGET_FILE:sample_mesh_points>
                   ${ISM_DATA_DIR}/meshes ${CMAKE_CURRENT_BINARY_DIR}/tool_test_out)
  set_tests_properties(tool PROPERTIES TIMEOUT 600)
endif()

# The examples, each on a small input (they write into their working directory).
if(TARGET sample_mesh_points)
  set(ISM_EXAMPLES_OUT ${CMAKE_CURRENT_BINARY_DIR}/examples_out)
  file(MAKE_DIRECTORY ${ISM_EXAMPLES_OUT})
  add_test(NAME examples_input
           COMMAND sample_mesh_points --seed 5 ${ISM_DATA_DIR}/meshes/sphere.off 4000
                   ${ISM_EXAMPLES_OUT}/sphere_points.xyz)
  set_tests_properties(examples_input PROPERTIES FIXTURES_SETUP ism_examples_input)
  foreach(example ism_reconstruction_example ism_surface_mesher_example ism_export_tets_example
                  bisection_triangulation_example)
    if(TARGET ${example})
      add_test(NAME ${example} COMMAND ${example} ${ISM_EXAMPLES_OUT}/sphere_points.xyz
               WORKING_DIRECTORY ${ISM_EXAMPLES_OUT})
      set_tests_properties(${example} PROPERTIES FIXTURES_REQUIRED ism_examples_input TIMEOUT 600)
    endif()
  endforeach()
endif()
