# covopt's libraries and its package components, written once.
#
#   covopt_add_library(<name>
#     SOURCES <file>...
#     [PUBLIC <item>...]            link items the public headers expose (usage requirements)
#     [PRIVATE <item>...]           link items only the sources use
#     [PACKAGE_DEPENDENCIES <args>...])
#
# makes the static (or, with BUILD_SHARED_LIBS, shared) library covopt_<name> with the alias
# covopt::<name>, its headers in <dir>/include (installed to include/), C++20, covopt's
# warnings, and installs it as the package component <name> of find_package(covopt):
#   - its own export set covopt-<name>-targets (lib/cmake/covopt/covopt-<name>-targets.cmake);
#   - lib/cmake/covopt/covopt-<name>-dependencies.cmake, which find_package(covopt COMPONENTS
#     <name>) loads: first the covopt components it links (any covopt::<other> in PUBLIC or
#     PRIVATE: a static library needs its private libraries at the consumer's link too), then
#     one find_dependency(<args>) per PACKAGE_DEPENDENCIES entry (one quoted string each, e.g.
#     "SUNDIALS 6.4 COMPONENTS cvodes"), then the targets. A third-party library that is a
#     link item must have its package here; a header-only one used in src/ only can be
#     PRIVATE $<BUILD_INTERFACE:...> and stay out of the package.
#
# Further settings go on the target covopt_<name> after the call (generated sources with
# target_sources, private include directories, ...).

# Warnings for our own targets only: covopt_warnings(<target>...).
# -Wno-missing-field-initializers: the scene's aggregates grow by members with default
# initializers (CoveringSpec's compressive curve and law), and a literal that names only the
# leading members, CoveringSpec{E, nu, b}, means "the rest as defaulted"; GCC 12 warns about it
# even for designated initializers.
function(covopt_warnings)
  foreach(target IN LISTS ARGN)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-missing-field-initializers
                           $<$<BOOL:${COVOPT_WARNINGS_AS_ERRORS}>:-Werror>)
  endforeach()
endfunction()

# toml++ for <target>'s own sources, header-only (TOML_HEADER_ONLY=1): Debian's toml++ also
# ships a shared library, which would be one more object to load at every start-up. Private:
# nothing of it reaches a target's users or the package.
function(covopt_use_toml target)
  get_target_property(include_dirs tomlplusplus::tomlplusplus INTERFACE_INCLUDE_DIRECTORIES)
  target_include_directories(${target} SYSTEM PRIVATE ${include_dirs})
  target_compile_definitions(${target} PRIVATE TOML_HEADER_ONLY=1)
endfunction()

function(covopt_add_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;PUBLIC;PRIVATE;PACKAGE_DEPENDENCIES")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "covopt_add_library(${name}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_SOURCES)
    message(FATAL_ERROR "covopt_add_library(${name}): no SOURCES")
  endif()
  set(target covopt_${name})
  add_library(${target} ${arg_SOURCES})
  add_library(covopt::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME ${target}
                        VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PUBLIC ${arg_PUBLIC} PRIVATE ${arg_PRIVATE})
  covopt_warnings(${target})

  install(TARGETS ${target} EXPORT covopt-${name}-targets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT covopt-${name}-targets NAMESPACE covopt::
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/covopt)
  export(EXPORT covopt-${name}-targets NAMESPACE covopt::
         FILE ${PROJECT_BINARY_DIR}/covopt-${name}-targets.cmake)

  # The component's package file: the covopt components it links, its find_dependency calls,
  # its targets.
  set(components)
  foreach(item IN LISTS arg_PUBLIC arg_PRIVATE)
    if(item MATCHES "^covopt::(.+)$")
      list(APPEND components ${CMAKE_MATCH_1})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES components)
  set(text "# covopt package component '${name}' (written by covopt_add_library)\n")
  foreach(component IN LISTS components)
    string(APPEND text "include(\"\${CMAKE_CURRENT_LIST_DIR}/covopt-${component}-dependencies.cmake\")\n"
                       "if(NOT covopt_FOUND)\n  return()\nendif()\n")
  endforeach()
  foreach(dependency IN LISTS arg_PACKAGE_DEPENDENCIES)
    string(APPEND text "find_dependency(${dependency})\n")
  endforeach()
  string(APPEND text "include(\"\${CMAKE_CURRENT_LIST_DIR}/covopt-${name}-targets.cmake\")\n")
  set(file ${PROJECT_BINARY_DIR}/covopt-${name}-dependencies.cmake)
  file(CONFIGURE OUTPUT ${file} CONTENT "${text}" @ONLY)
  install(FILES ${file} DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/covopt)
  set_property(GLOBAL APPEND PROPERTY COVOPT_COMPONENTS ${name})
endfunction()

# The package: covoptConfig.cmake (components as listed by covopt_add_library) and its
# version file, in the build tree and installed. Call once, after every covopt_add_library.
function(covopt_install_package)
  get_property(COVOPT_COMPONENTS GLOBAL PROPERTY COVOPT_COMPONENTS)
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/covoptConfig.cmake.in
    ${PROJECT_BINARY_DIR}/covoptConfig.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/covopt)
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/covoptConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/covoptConfig.cmake ${PROJECT_BINARY_DIR}/covoptConfigVersion.cmake
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/covopt)
endfunction()
