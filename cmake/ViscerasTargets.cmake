# Helpers that give every project target the same language level, warnings and include root.
# Warnings are errors for project code only: dependencies come in as SYSTEM includes.

function(viscera_apply_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Woverloaded-virtual
                                           -Wdouble-promotion
                                           # GCC 12 reports std::string concatenation as
                                           # overlapping memcpy at -O2 (GCC bug 105651).
                                           -Wno-restrict)
  if(VISCERA_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# viscera_add_library(NAME SOURCES … PUBLIC_LINKS … PRIVATE_LINKS …)
function(viscera_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_LINKS;PRIVATE_LINKS" ${ARGN})
  add_library(${name} ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_compile_features(${name} PUBLIC cxx_std_20)
  target_link_libraries(${name} PUBLIC ${ARG_PUBLIC_LINKS} PRIVATE ${ARG_PRIVATE_LINKS})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  viscera_apply_warnings(${name})
endfunction()

# viscera_add_executable(NAME SOURCES … LINKS …)
function(viscera_add_executable name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LINKS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LINKS})
  viscera_apply_warnings(${name})
endfunction()
