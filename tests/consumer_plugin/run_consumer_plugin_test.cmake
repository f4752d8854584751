# Installs the rtlab build tree into a fresh prefix, then configures and builds tests/consumer_plugin (a
# plugin module made with rtlab_add_plugin and a program that loads it) against that prefix alone, and
# runs the program: it loads the module and the installed toon example by name and renders with them.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()
run(${CMAKE_COMMAND} --install ${RTLAB_BUILD_DIR} --prefix ${prefix})
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
    "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}"
    "-DCMAKE_MODULE_LINKER_FLAGS=${MODULE_LINKER_FLAGS}")
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/rtlab_consumer_plugin_host ${WORK_DIR}/build/plugins ${prefix}/${PLUGIN_INSTALL_DIR}
    ${WORK_DIR}/consumer_plugin.png)
message(STATUS "plugin consumer built against ${prefix}, loaded its module and rendered")
