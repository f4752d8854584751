# rtlab_add_library(<name> SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...] [PACKAGE_DEPS ...])
#
# Creates the static library rtlab_<name> with alias rtlab::<name>, its public headers under
# libs/<name>/include, and (for the top-level project) its install rules and exported targets.
# PACKAGE_DEPS names the external packages that a consumer of the installed component must find
# (find_dependency lines in rtlabConfig.cmake); they are recorded per component.
function(rtlab_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS;PACKAGE_DEPS;RTLAB_DEPS" ${ARGN})
  set(target rtlab_${name})
  add_library(${target} STATIC ${ARG_SOURCES})
  add_library(rtlab::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON)
  target_compile_features(${target} PUBLIC cxx_std_20)
  # The ray-triangle and slab tests are inline in public headers, so they compile with the caller's flags.
  # Their exactness (watertight edge functions that agree across a shared edge) needs every a*b - c*d
  # rounded twice: GCC contracts it into one FMA whenever the target has FMA (-march=native, haswell) and
  # Clang within an expression by default. A usage requirement, so consumers of the installed package
  # get it too.
  target_compile_options(${target} PUBLIC $<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang,AppleClang>:-ffp-contract=off>)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  foreach(dep IN LISTS ARG_RTLAB_DEPS)
    target_link_libraries(${target} PUBLIC rtlab::${dep})
  endforeach()
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS}
    $<BUILD_INTERFACE:rtlab_warnings>)

  set_property(GLOBAL APPEND PROPERTY RTLAB_COMPONENTS ${name})
  set_property(GLOBAL PROPERTY RTLAB_COMPONENT_${name}_RTLAB_DEPS "${ARG_RTLAB_DEPS}")
  set_property(GLOBAL PROPERTY RTLAB_COMPONENT_${name}_PACKAGE_DEPS "${ARG_PACKAGE_DEPS}")

  if(RTLAB_INSTALL)
    install(TARGETS ${target} EXPORT rtlab_${name}_targets
      ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
    install(EXPORT rtlab_${name}_targets NAMESPACE rtlab:: FILE rtlab_${name}_targets.cmake
      DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rtlab)
  endif()
endfunction()

# rtlab_add_precompiled_header(<donor> <header> LIBS ...): an object target that only precompiles <header> (with
# RTLAB_PRECOMPILE_HEADERS), compiled with the flags LIBS pass on, for rtlab_reuse_precompiled_header. One
# precompiled copy serves every target of a kind, since the headers worth it (Catch2, CLI11) are included by
# many files across many targets.
function(rtlab_add_precompiled_header donor header)
  cmake_parse_arguments(ARG "" "" "LIBS" ${ARGN})
  if(RTLAB_PRECOMPILE_HEADERS)
    file(CONFIGURE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/${donor}.cpp CONTENT "// Precompiles ${header}.\n")
    add_library(${donor} OBJECT ${CMAKE_CURRENT_BINARY_DIR}/${donor}.cpp)
    target_link_libraries(${donor} PRIVATE ${ARG_LIBS} rtlab_warnings)
    target_precompile_headers(${donor} PRIVATE ${header})
  endif()
endfunction()

# rtlab_reuse_precompiled_header(<target> <donor>): <target>'s files start from <donor>'s precompiled header.
# With it, GCC 12 reports false stringop-overflow and array-bounds warnings inside libstdc++ for a literal +
# std::string (GCC bug 105651, of the family -Wno-restrict answers in rtlab_warnings): a header read from a
# precompiled file no longer silences the middle end's warnings as a system header. They are turned off for the
# reusers, all tests and apps, whether precompiled or not, so a build under ccache (no precompiled headers) warns
# exactly as CI does; the libraries keep them, and the sanitizer run checks the reusers' real overflows.
function(rtlab_reuse_precompiled_header target donor)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-stringop-overflow -Wno-stringop-overread -Wno-array-bounds)
  endif()
  if(TARGET ${donor})
    target_precompile_headers(${target} REUSE_FROM ${donor})
  endif()
endfunction()

# rtlab_add_app(<name> SOURCES ... LIBS ...): an executable named rtlab-<name> in bin/. Apps that parse flags
# (CLI11, directly or through rtlab_app_common) reuse the precompiled CLI11.
function(rtlab_add_app name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(rtlab_app_${name} ${ARG_SOURCES})
  set_target_properties(rtlab_app_${name} PROPERTIES OUTPUT_NAME rtlab-${name})
  target_link_libraries(rtlab_app_${name} PRIVATE ${ARG_LIBS} rtlab_warnings)
  if("CLI11::CLI11" IN_LIST ARG_LIBS OR "rtlab_app_common" IN_LIST ARG_LIBS)
    rtlab_reuse_precompiled_header(rtlab_app_${name} rtlab_cli11_pch)
  endif()
  if(RTLAB_INSTALL)
    install(TARGETS rtlab_app_${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endfunction()
