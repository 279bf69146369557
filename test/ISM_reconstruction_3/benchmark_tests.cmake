# The quick benchmark set (bunny and eight at 5,000 points, every method): fails if a method
# did not run or produced no scores. Included from test/ISM_reconstruction_3/CMakeLists.txt.
if(TARGET benchmark_reconstruction)
  add_test(NAME benchmark_quick
           COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/benchmark/ISM_reconstruction_3/run_benchmark.py
                   --quick --build ${CMAKE_BINARY_DIR}
                   --exe $<TARGET_FILE:benchmark_reconstruction> --data ${ISM_DATA_DIR}/meshes
                   --out ${CMAKE_CURRENT_BINARY_DIR}/benchmark_quick)
  set_tests_properties(benchmark_quick PROPERTIES TIMEOUT 600)
endif()
