# Helpers shared by the project's libraries (ompl_mm, ompl_phys).
include(CMakePackageConfigHelpers)

# Gives library <name> its include paths (the source tree; <prefix>/include once installed), an
# alias <name>::<name>, our warnings, and installs it with its headers into export set <name>Targets.
function(ompl_project_library name)
  add_library(${name}::${name} ALIAS ${name})
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_options(${name} PRIVATE ${OMPL_MM_WARNINGS})
  set_target_properties(${name} PROPERTIES UNITY_BUILD ${OMPL_MM_UNITY_BUILD})
  install(TARGETS ${name} EXPORT ${name}Targets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${name}
    FILES_MATCHING PATTERN "*.h" PATTERN "src" EXCLUDE)
endfunction()

# Installs the CMake package of library <name>: find_package(<name>) gives <name>::<name>; the
# config file comes from cmake/<name>Config.cmake.in.
function(ompl_install_package name)
  set(dir ${CMAKE_INSTALL_LIBDIR}/cmake/${name})
  install(EXPORT ${name}Targets NAMESPACE ${name}:: DESTINATION ${dir})
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/${name}Config.cmake.in
    ${PROJECT_BINARY_DIR}/${name}Config.cmake INSTALL_DESTINATION ${dir})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/${name}ConfigVersion.cmake
    COMPATIBILITY SameMajorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/${name}Config.cmake ${PROJECT_BINARY_DIR}/${name}ConfigVersion.cmake
    DESTINATION ${dir})
endfunction()
