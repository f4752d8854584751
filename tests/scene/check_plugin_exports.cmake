# Checks that each module in MODULES ('|'-separated) defines exactly rtlab_plugin_query and
# rtlab_plugin_register in its dynamic symbol table: rtlab's static libraries and every template it
# instantiated stay hidden, so two modules (or a module and the host) can never bind to each other's code.
find_program(NM nm REQUIRED)
string(REPLACE "|" ";" modules "${MODULES}")
foreach(module IN LISTS modules)
  execute_process(COMMAND ${NM} -D --defined-only --format=posix ${module}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "nm failed on ${module}: ${err}")
  endif()
  string(REGEX MATCHALL "[^\n]+" lines "${out}")
  set(names "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE " .*" "" name "${line}")
    list(APPEND names ${name})
  endforeach()
  list(SORT names)
  if(NOT names STREQUAL "rtlab_plugin_query;rtlab_plugin_register")
    message(FATAL_ERROR "${module} exports: ${names}\n(expected rtlab_plugin_query;rtlab_plugin_register)")
  endif()
  message(STATUS "${module}: exports ${names}")
endforeach()
