# `cmake --install`: the dtlab binary, the kernel's and predicates' headers and static
# libraries, and a CMake package (find_package(dtlab) -> dtlab::kernel, dtlab::predicates).
# Tested by examples/install_test.cmake (CTest install_example).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(DTLAB_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/dtlab)
# Headers are included as "kernel/..." and "predicates/...": from the source root in a
# build, from include/dtlab once installed.
set_target_properties(dtlab_predicates PROPERTIES EXPORT_NAME predicates INTERFACE_INCLUDE_DIRECTORIES
  "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>;$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/dtlab>")
set_target_properties(dtlab_kernel PROPERTIES EXPORT_NAME kernel)
# A sanitizer build's libraries need the sanitizer runtimes wherever they are linked.
if(DTLAB_SANITIZE)
  target_link_options(dtlab_predicates INTERFACE -fsanitize=address,undefined)
endif()
install(TARGETS dtlab_predicates dtlab_kernel EXPORT dtlabTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(module predicates kernel)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${module}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dtlab/${module}
          FILES_MATCHING PATTERN "*.hpp" PATTERN "tests" EXCLUDE)
endforeach()
if(TARGET dtlab)
  install(TARGETS dtlab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(EXPORT dtlabTargets NAMESPACE dtlab:: DESTINATION ${DTLAB_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/dtlabConfig.cmake.in
  ${PROJECT_BINARY_DIR}/dtlabConfig.cmake INSTALL_DESTINATION ${DTLAB_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_BINDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dtlabConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dtlabConfig.cmake ${PROJECT_BINARY_DIR}/dtlabConfigVersion.cmake
        DESTINATION ${DTLAB_CMAKE_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CITATION.cff DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The C++ API example, built against an installed copy (needs the cli module for dtlab).
if(TARGET dtlab)
  add_test(NAME install_example
           COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${PROJECT_BINARY_DIR} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
                   -DWORK=${PROJECT_BINARY_DIR}/install_example -DGENERATOR=${CMAKE_GENERATOR}
                   -DCXX=${CMAKE_CXX_COMPILER} -P ${PROJECT_SOURCE_DIR}/examples/install_test.cmake)
  set_tests_properties(install_example PROPERTIES LABELS install TIMEOUT 600)
endif()
