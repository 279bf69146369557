# Extract the meshes the examples, tests and benchmarks use from libcgal-demo's
# data tarball (Debian: /usr/share/doc/libcgal-dev/data.tar.gz) into
# ${ISM_DATA_DIR}/meshes. Nothing is committed: the data stay Debian's.
set(ISM_DATA_TARBALL "/usr/share/doc/libcgal-dev/data.tar.gz" CACHE FILEPATH
    "libcgal-demo's data tarball")
set(ISM_DATA_DIR "${CMAKE_BINARY_DIR}/data" CACHE PATH "Where extracted meshes go")
set(ISM_DATA_MESHES bunny00.off knot1.off knot2.off ChineseDragon-10kv.off eight.off
    double-torus-example.off 3torus.off sphere.off)
set(_ism_missing "")
foreach(m ${ISM_DATA_MESHES})
  if(NOT EXISTS "${ISM_DATA_DIR}/meshes/${m}")
    list(APPEND _ism_missing "data/meshes/${m}")
  endif()
endforeach()
if(_ism_missing)
  if(EXISTS "${ISM_DATA_TARBALL}")
    file(MAKE_DIRECTORY "${ISM_DATA_DIR}")
    execute_process(COMMAND tar -xzf "${ISM_DATA_TARBALL}" --strip-components=1 ${_ism_missing}
                    WORKING_DIRECTORY "${ISM_DATA_DIR}" RESULT_VARIABLE _ism_tar)
    if(NOT _ism_tar EQUAL 0)
      message(WARNING "Could not extract ${_ism_missing} from ${ISM_DATA_TARBALL}")
    endif()
  else()
    message(WARNING "${ISM_DATA_TARBALL} not found (apt-get install libcgal-demo): "
                    "tests and benchmarks on real data will fail")
  endif()
endif()
