# `velocity batch` runs the Python job runner: a job of a real model and a missing one
# renders the real one's views, reports the missing one in the manifest and exits 3;
# the same job without the missing model then exits 0, resuming (nothing left to do).
#   cmake -DVELOCITY=... -DMODEL=... -DWORK=... [-DRUN_ENV=VAR=value|...] [-DNO_LEAKS=ON] -P cli_batch.cmake
# RUN_ENV: variables for the program (the sanitizers' preloads), '|'-separated.
set(run ${VELOCITY})
if(RUN_ENV)
  string(REPLACE "|" ";" env_list "${RUN_ENV}")
  if(NO_LEAKS)
    list(APPEND env_list "ASAN_OPTIONS=$ENV{ASAN_OPTIONS}:detect_leaks=0")
  endif()
  set(run env ${env_list} ${VELOCITY})
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/job.json "{\"models\": [\"${MODEL}\", \"missing.asc\"], \"size\": [48, 32],
  \"views\": {\"type\": \"orbit\", \"count\": 3}, \"outputs\": [\"color\", \"depth\", \"mask\"]}")
execute_process(COMMAND ${run} batch ${WORK}/job.json --out ${WORK}/out --progress never
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 3)
  message(FATAL_ERROR "expected exit status 3 (a model failed), got ${rc}")
endif()
get_filename_component(stem ${MODEL} NAME_WE)
foreach(f 000000.color.png 000002.depth.npy 000002.mask.png)
  if(NOT EXISTS ${WORK}/out/${stem}/${f})
    message(FATAL_ERROR "missing output ${WORK}/out/${stem}/${f}")
  endif()
endforeach()
file(READ ${WORK}/out/manifest.json manifest)
if(NOT manifest MATCHES "missing.asc")
  message(FATAL_ERROR "the manifest does not report missing.asc")
endif()
file(WRITE ${WORK}/job.json "{\"models\": [\"${MODEL}\"], \"size\": [48, 32],
  \"views\": {\"type\": \"orbit\", \"count\": 3}, \"outputs\": [\"color\", \"depth\", \"mask\"]}")
execute_process(COMMAND ${run} batch ${WORK}/job.json --out ${WORK}/out --progress always
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT err MATCHES "3/3 views done")
  message(FATAL_ERROR "the second run should resume and finish: exit ${rc}")
endif()
