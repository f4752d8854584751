# The installed package: one component per library, each with its own exported targets, the rtlab
# components it depends on and the external packages it needs (see rtlabConfig.cmake.in).
include(CMakePackageConfigHelpers)
get_property(RTLAB_COMPONENTS GLOBAL PROPERTY RTLAB_COMPONENTS)
set(RTLAB_COMPONENT_TABLE "")
foreach(c IN LISTS RTLAB_COMPONENTS)
  get_property(rdeps GLOBAL PROPERTY RTLAB_COMPONENT_${c}_RTLAB_DEPS)
  get_property(pdeps GLOBAL PROPERTY RTLAB_COMPONENT_${c}_PACKAGE_DEPS)
  string(REPLACE ";" " " rdeps "${rdeps}")
  string(REPLACE ";" "|" pdeps "${pdeps}")
  string(APPEND RTLAB_COMPONENT_TABLE "set(_rtlab_${c}_deps ${rdeps})\nset(_rtlab_${c}_packages \"${pdeps}\")\n")
endforeach()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rtlabConfig.cmake.in
  ${PROJECT_BINARY_DIR}/rtlabConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rtlab)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rtlabConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rtlabConfig.cmake ${PROJECT_BINARY_DIR}/rtlabConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/RtlabPlugin.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rtlab)
