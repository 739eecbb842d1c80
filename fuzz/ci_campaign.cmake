# The CI campaign (issue 6, "Done when"), run by CTest (fuzz/CMakeLists.txt):
#   cmake -DDTLAB=<dtlab> -DOUT=<dir> -DPREDICATES=<list> -DEXPECT=clean|failures -P ci_campaign.cmake
# Runs `dtlab fuzz --family all --cases 20 --predicates <list> --perturb sos,none --jobs 2`
# in a fresh OUT (a campaign resumes from an existing folder, so it is removed first).
#   EXPECT=clean:    exit 0 and "0 failing".
#   EXPECT=failures: exit 1, some failures, each with a shrunk .node/.json in
#                    OUT/corpus (none larger than its original, at least one strictly
#                    smaller); the corpus replays to the same failures with the same
#                    backend, and to zero failures with adaptive and exact.
foreach(var DTLAB OUT PREDICATES EXPECT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "ci_campaign.cmake: -D${var}=... is required")
  endif()
endforeach()

function(run_dtlab out_rc out_text)
  execute_process(COMMAND "${DTLAB}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE text
                  ERROR_VARIABLE text TIMEOUT 120)
  set(${out_rc} "${rc}" PARENT_SCOPE)
  set(${out_text} "${text}" PARENT_SCOPE)
endfunction()

function(fail why text)
  string(LENGTH "${text}" n)
  if(n GREATER 4000)
    math(EXPR from "${n} - 4000")
    string(SUBSTRING "${text}" ${from} 4000 text)
  endif()
  message(FATAL_ERROR "ci_campaign: ${why}\n--- dtlab output (tail) ---\n${text}")
endfunction()

file(REMOVE_RECURSE "${OUT}")
run_dtlab(rc text fuzz --family all --cases 20 --predicates "${PREDICATES}" --perturb sos,none
          --jobs 2 --out "${OUT}")
if(NOT text MATCHES "([0-9]+) results \\([^)]*\\), ([0-9]+) failing")
  fail("no summary line in the output (exit ${rc})" "${text}")
endif()
set(results ${CMAKE_MATCH_1})
set(failing ${CMAKE_MATCH_2})
message(STATUS "${PREDICATES}: ${results} results, ${failing} failing, exit ${rc}")
if(results EQUAL 0)
  fail("the campaign ran no case" "${text}")
endif()

if(EXPECT STREQUAL "clean")
  if(NOT rc EQUAL 0 OR NOT failing EQUAL 0)
    fail("expected zero failures and exit 0, got ${failing} failing, exit ${rc}" "${text}")
  endif()
  return()
endif()

if(NOT EXPECT STREQUAL "failures")
  message(FATAL_ERROR "ci_campaign.cmake: EXPECT must be clean or failures")
endif()
if(NOT rc EQUAL 1 OR failing EQUAL 0)
  fail("expected failures and exit 1, got ${failing} failing, exit ${rc}" "${text}")
endif()
file(GLOB nodes "${OUT}/corpus/*.node")
list(LENGTH nodes corpus_size)
if(NOT corpus_size EQUAL failing)
  fail("${failing} failing but ${corpus_size} corpus entries" "${text}")
endif()
set(shrunk 0)
set(before 0)
set(after 0)
foreach(node IN LISTS nodes)
  string(REGEX REPLACE "\\.node$" ".json" sidecar "${node}")
  if(NOT EXISTS "${sidecar}")
    fail("${node} has no .json sidecar" "")
  endif()
  file(READ "${sidecar}" json)
  string(JSON points GET "${json}" points)
  string(JSON original GET "${json}" points_original)
  string(JSON reproduce GET "${json}" reproduce)
  if(points GREATER original OR NOT reproduce MATCHES "^dtlab fuzz --replay ")
    fail("${sidecar}: ${points} points from ${original}, reproduce '${reproduce}'" "${json}")
  endif()
  if(points LESS original)
    math(EXPR shrunk "${shrunk} + 1")
  endif()
  math(EXPR before "${before} + ${original}")
  math(EXPR after "${after} + ${points}")
endforeach()
message(STATUS "corpus: ${corpus_size} entries, ${shrunk} shrunk, ${before} -> ${after} points")
if(shrunk EQUAL 0)
  fail("no failure was shrunk" "")
endif()

# The corpus reproduces: the same failures with the recorded backend, none with the
# robust ones.
run_dtlab(rc text fuzz --replay "${OUT}/corpus")
if(NOT rc EQUAL 1 OR NOT text MATCHES "${corpus_size} replayed, ${corpus_size} failing")
  fail("replaying the corpus did not reproduce all ${corpus_size} failures (exit ${rc})" "${text}")
endif()
run_dtlab(rc text fuzz --replay "${OUT}/corpus" --predicates adaptive,exact --perturb sos,none)
if(NOT rc EQUAL 0 OR NOT text MATCHES " 0 failing")
  fail("the robust backends failed on the corpus (exit ${rc})" "${text}")
endif()
