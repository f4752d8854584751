# Installs the rtlab build tree into a fresh prefix, then configures, builds and runs a consumer project
# against that prefix alone: the proof that find_package(rtlab COMPONENTS ...) and rtlab_add_plugin work from
# an install. Used by tests/consumer, tests/consumer_all and tests/consumer_plugin, which differ only in
#   CONSUMER_EXE         the program to run, relative to the consumer's build folder
#   CONSUMER_ARGS        its arguments, separated by '|' (add_test would split a ';' list); {build} and
#                        {prefix} stand for the consumer's build folder and the install prefix
#   MODULE_LINKER_FLAGS  for consumers that build a module (optional)
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()
set(args "")
if(DEFINED CONSUMER_ARGS AND NOT CONSUMER_ARGS STREQUAL "")
  string(REPLACE "|" ";" args "${CONSUMER_ARGS}")
  string(REPLACE "{build}" "${build}" args "${args}")
  string(REPLACE "{prefix}" "${prefix}" args "${args}")
endif()
run(${CMAKE_COMMAND} --install ${RTLAB_BUILD_DIR} --prefix ${prefix})
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${build}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
    "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}"
    "-DCMAKE_MODULE_LINKER_FLAGS=${MODULE_LINKER_FLAGS}")
run(${CMAKE_COMMAND} --build ${build})
run(${build}/${CONSUMER_EXE} ${args})
message(STATUS "consumer ${CONSUMER_EXE} built against ${prefix} and ran")
