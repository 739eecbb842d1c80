# The library dtlab_build_info: dtlab/build_info.hpp with a source generated on every
# build (the git commit can change without a reconfigure; see build_info.cmake).
set(DTLAB_GENERATED ${PROJECT_BINARY_DIR}/generated)
configure_file(${PROJECT_SOURCE_DIR}/cmake/build_info.hpp ${DTLAB_GENERATED}/dtlab/build_info.hpp COPYONLY)
set(tetgen_version "not found")
find_program(DTLAB_TETGEN_BINARY tetgen)
if(DTLAB_TETGEN_BINARY)
  set(tetgen_version "found (${DTLAB_TETGEN_BINARY}), version unknown")
  execute_process(COMMAND dpkg-query -W -f=\${Version} tetgen OUTPUT_VARIABLE out RESULT_VARIABLE rc ERROR_QUIET)
  if(rc EQUAL 0 AND out)
    set(tetgen_version "${out} (Debian package)")
  endif()
endif()
add_custom_target(dtlab_build_info_gen
  BYPRODUCTS ${DTLAB_GENERATED}/dtlab/build_info.cpp
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DOUT=${DTLAB_GENERATED}/dtlab
          -DDTLAB_VERSION=${PROJECT_VERSION} "-DDTLAB_COMPILER=${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}"
          -DDTLAB_BUILD_TYPE=${CMAKE_BUILD_TYPE} -DDTLAB_CGAL_VERSION=${CGAL_VERSION}
          "-DDTLAB_TETGEN_VERSION=${tetgen_version}" -P ${PROJECT_SOURCE_DIR}/cmake/build_info.cmake
  COMMENT "dtlab build info (version, git commit)" VERBATIM)
add_library(dtlab_build_info STATIC ${DTLAB_GENERATED}/dtlab/build_info.cpp)
add_dependencies(dtlab_build_info dtlab_build_info_gen)
target_include_directories(dtlab_build_info PUBLIC $<BUILD_INTERFACE:${DTLAB_GENERATED}>)
target_link_libraries(dtlab_build_info PRIVATE ${GMP_LIBRARY})
