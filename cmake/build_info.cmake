# Writes OUT/dtlab/build_info.cpp: the version, the git commit of SOURCE_DIR at build
# time ("unknown" outside a git checkout or without git) and the third-party versions
# found at configure time. Run by the target dtlab_build_info_gen on every build;
# configure_file rewrites the file only when its text changes, so an unchanged commit
# recompiles nothing.
set(commit "unknown")
set(dirty "")
find_program(GIT git)
if(GIT)
  execute_process(COMMAND ${GIT} -C ${SOURCE_DIR} rev-parse --short=12 HEAD
                  OUTPUT_VARIABLE out RESULT_VARIABLE rc ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(rc EQUAL 0 AND out)
    set(commit "${out}")
    execute_process(COMMAND ${GIT} -C ${SOURCE_DIR} status --porcelain --untracked-files=no
                    OUTPUT_VARIABLE changes RESULT_VARIABLE rc ERROR_QUIET)
    if(rc EQUAL 0 AND NOT changes STREQUAL "")
      set(dirty "-dirty")
    endif()
  endif()
endif()
set(DTLAB_GIT_COMMIT "${commit}${dirty}")
configure_file(${SOURCE_DIR}/cmake/build_info.cpp.in ${OUT}/build_info.cpp @ONLY)
