# clothbench_optional_backend: one optional collider backend, everything its build needs in one call
# (in the manner of tests/CMakeLists.txt's clothbench_add_test).
#
#   clothbench_optional_backend(NAME collide_foo OPTION CLOTHBENCH_WITH_FOO DOC "Build the foo collider"
#     SOURCES src/foo_collider.cpp
#     [PACKAGE foo 1.2]            # find_package(foo 1.2 REQUIRED) when the option is on
#     [PKG_CONFIG FOO foo]         # pkg_check_modules(FOO REQUIRED IMPORTED_TARGET foo): PkgConfig::FOO
#     [PUBLIC libs...] [PRIVATE libs...])
#
# - the option OPTION (default ON; -DOPTION=OFF leaves the backend out; one declared before keeps its value);
# - when it is on: the library clothbench_NAME and its alias clothbench::NAME, with the calling folder's
#   include/ as public headers, linking clothbench::sim and PUBLIC publicly, PRIVATE and clothbench::warnings
#   privately; clothbench::bench links every such library (bench/CMakeLists.txt);
# - the define OPTION in clothbench/config.h (cmake/config.h.in), for the registry's entry
#   (bench/src/registry.cpp) to guard its include and factory with.
# The generated config.h is written once every backend has been declared (the top CMakeLists.txt).

define_property(GLOBAL PROPERTY CLOTHBENCH_BACKENDS BRIEF_DOCS "clothbench::NAME of every backend built"
                FULL_DOCS "The libraries clothbench_optional_backend made, in the order they were declared.")
define_property(GLOBAL PROPERTY CLOTHBENCH_BACKEND_DEFINES BRIEF_DOCS "config.h lines of the backends"
                FULL_DOCS "One #define (option on) or commented #undef (option off) per backend option.")

function(clothbench_optional_backend)
  cmake_parse_arguments(B "" "NAME;OPTION;DOC" "SOURCES;PACKAGE;PKG_CONFIG;PUBLIC;PRIVATE" ${ARGN})
  if(NOT B_NAME OR NOT B_OPTION OR NOT B_SOURCES)
    message(FATAL_ERROR "clothbench_optional_backend: NAME, OPTION and SOURCES are required")
  endif()
  option(${B_OPTION} "${B_DOC}" ON)
  # the same lines #cmakedefine writes, so config.h reads as it did when it listed each option
  if(NOT ${B_OPTION})
    set_property(GLOBAL APPEND PROPERTY CLOTHBENCH_BACKEND_DEFINES "/* #undef ${B_OPTION} */")
    return()
  endif()
  set_property(GLOBAL APPEND PROPERTY CLOTHBENCH_BACKEND_DEFINES "#define ${B_OPTION}")
  if(B_PACKAGE)
    find_package(${B_PACKAGE} REQUIRED)
  endif()
  if(B_PKG_CONFIG)
    list(POP_FRONT B_PKG_CONFIG prefix)
    pkg_check_modules(${prefix} REQUIRED IMPORTED_TARGET ${B_PKG_CONFIG})
  endif()
  add_library(clothbench_${B_NAME} ${B_SOURCES})
  add_library(clothbench::${B_NAME} ALIAS clothbench_${B_NAME})
  target_include_directories(clothbench_${B_NAME} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  target_link_libraries(clothbench_${B_NAME} PUBLIC clothbench::sim ${B_PUBLIC} PRIVATE ${B_PRIVATE} clothbench::warnings)
  set_property(GLOBAL APPEND PROPERTY CLOTHBENCH_BACKENDS clothbench::${B_NAME})
endfunction()
