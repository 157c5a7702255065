# `cmake --install BUILD [--prefix P]` installs the libraries, their headers (under
# include/ccdlab/, so that ccdlab's ccd/ folder never mixes with libccd's), the ccdlab
# program and a CMake package: find_package(ccdlab) gives ccdlab::core, ccdlab::bounds,
# ccdlab::pipeline, ccdlab::cloth, ccdlab::generators, ccdlab::runner and ccdlab::ccdlab (all of them).
include(CMakePackageConfigHelpers)

add_library(ccdlab_all INTERFACE)
add_library(ccdlab::ccdlab ALIAS ccdlab_all)
set_target_properties(ccdlab_all PROPERTIES EXPORT_NAME ccdlab)
target_link_libraries(ccdlab_all INTERFACE ccdlab_core ccdlab_bounds ccdlab_pipeline ccdlab_cloth ccdlab_generators
  ccdlab_runner)

set(CCDLAB_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ccdlab)
install(TARGETS ccdlab_core ccdlab_bounds ccdlab_pipeline ccdlab_cloth ccdlab_generators ccdlab_runner ccdlab_all
  EXPORT ccdlabTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ccdlab)
install(TARGETS ccdlab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The scripts behind `ccdlab report` and `ccdlab animate` (cli/python_script.hpp).
install(PROGRAMS ${PROJECT_SOURCE_DIR}/scripts/report.py ${PROJECT_SOURCE_DIR}/scripts/animate.py
  DESTINATION ${CMAKE_INSTALL_DATADIR}/ccdlab/scripts)
install(FILES ${PROJECT_SOURCE_DIR}/scripts/results_json.py DESTINATION ${CMAKE_INSTALL_DATADIR}/ccdlab/scripts)
foreach(dir ccd bounds pipeline cloth generators experiments)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ccdlab/${dir}
    FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(EXPORT ccdlabTargets NAMESPACE ccdlab:: DESTINATION ${CCDLAB_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ccdlabConfig.cmake.in
  ${PROJECT_BINARY_DIR}/ccdlabConfig.cmake INSTALL_DESTINATION ${CCDLAB_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ccdlabConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ccdlabConfig.cmake ${PROJECT_BINARY_DIR}/ccdlabConfigVersion.cmake
  DESTINATION ${CCDLAB_CMAKE_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/ccdlab)
