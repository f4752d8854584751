# rtlab_add_plugin(<name> SOURCES ... [LIBS ...] [OUTPUT_DIRECTORY dir] [INSTALL_DESTINATION dir])
#
# Builds the plugin module <name>.so (no "lib" prefix: a scene names it "<name>") from SOURCES, for
# rtlab's own examples and for outside projects alike (find_package(rtlab) includes this file).
#
# The module links rtlab's static libraries (rtlab::render and what it brings, plus LIBS) PRIVATELY and
# keeps all of them to itself: it is compiled with hidden visibility, linked with --exclude-libs,ALL and a
# version script that exports only rtlab_plugin_query and rtlab_plugin_register, and with --no-undefined,
# so every symbol it needs comes from its own link line, never from the program that loads it.
#   OUTPUT_DIRECTORY     where the module is written (default: the library output directory, else the
#                        current binary directory)
#   INSTALL_DESTINATION  install the module there (rtlab's own examples: lib/rtlab/plugins, the folder
#                        rtlab's programs search)
function(rtlab_add_plugin name)
  cmake_parse_arguments(ARG "" "OUTPUT_DIRECTORY;INSTALL_DESTINATION" "SOURCES;LIBS" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "rtlab_add_plugin(${name}): no SOURCES")
  endif()
  if(NOT TARGET rtlab::scene)
    message(FATAL_ERROR "rtlab_add_plugin(${name}) needs rtlab::scene: find_package(rtlab COMPONENTS scene)")
  endif()
  add_library(${name} MODULE ${ARG_SOURCES})
  set_target_properties(${name} PROPERTIES
    PREFIX "" SUFFIX ".so"
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
    POSITION_INDEPENDENT_CODE ON)
  if(ARG_OUTPUT_DIRECTORY)
    set_target_properties(${name} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIRECTORY})
  endif()
  target_compile_features(${name} PRIVATE cxx_std_20)
  target_link_libraries(${name} PRIVATE rtlab::scene ${ARG_LIBS})

  set(version_script ${CMAKE_CURRENT_BINARY_DIR}/${name}_exports.map)
  file(CONFIGURE OUTPUT ${version_script}
    CONTENT "{\n  global: rtlab_plugin_query; rtlab_plugin_register;\n  local: *;\n};\n")
  target_link_options(${name} PRIVATE
    LINKER:--exclude-libs,ALL LINKER:--version-script=${version_script} LINKER:--no-undefined
    LINKER:--as-needed)
  set_property(TARGET ${name} APPEND PROPERTY LINK_DEPENDS ${version_script})

  if(ARG_INSTALL_DESTINATION)
    install(TARGETS ${name} LIBRARY DESTINATION ${ARG_INSTALL_DESTINATION})
  endif()
endfunction()
