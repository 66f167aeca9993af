# Precompiled headers (issue 51: the build's time). About two thirds of a typical translation
# unit's compile time here is parsing the same third-party and standard headers (Eigen, fmt,
# GoogleTest, <filesystem>: doc/notes/testTime.md); they are compiled once for each kind of
# target, into a precompiled header that every target of that kind reuses. Only headers from
# outside the project are precompiled (a change to a project header rebuilds what includes it,
# as before). A source that forgets one of these standard #includes compiles with them and not
# without: -DISPH_PRECOMPILED_HEADERS=OFF builds as before.

option(ISPH_PRECOMPILED_HEADERS "Precompile the third-party and standard headers of each library and test" ON)

set(ISPH_PCH_COMMON
    <Eigen/Core>
    <fmt/format.h>
    <algorithm>
    <cmath>
    <filesystem>
    <fstream>
    <functional>
    <map>
    <memory>
    <optional>
    <sstream>
    <string>
    <string_view>
    <vector>)

# One precompiled header per kind of target (shared library: position-independent; test:
# with GoogleTest; other executable), compiled by a target of its own with only the flags and
# macros every target of that kind has (the C++ standard, the warnings, NDEBUG, OpenMP, fmt's
# FMT_SHARED): GCC uses a precompiled header only where the macros it was made with are defined
# the same way, so a target's own definitions (ISPH_ETC_DIR, the test executables' paths) stay
# out of it. -Winvalid-pch says when one is not used.
function(isph_precompiled_header_owner kind)
  set(owner isphPrecompiled${kind})
  if(TARGET ${owner})
    return()
  endif()
  set(source ${CMAKE_BINARY_DIR}/precompiledHeaders/${kind}.cpp)
  # (written only when it changes: a new time stamp would rebuild everything at each cmake run)
  file(CONFIGURE OUTPUT ${source} CONTENT "// The translation unit that makes the ${kind} targets' precompiled header.\n")
  add_library(${owner} OBJECT ${source})
  set(headers ${ISPH_PCH_COMMON})
  target_link_libraries(${owner} PRIVATE Eigen3::Eigen fmt::fmt)
  if(OpenMP_CXX_FOUND)
    target_link_libraries(${owner} PRIVATE OpenMP::OpenMP_CXX)
  endif()
  if(kind STREQUAL "Test")
    target_link_libraries(${owner} PRIVATE GTest::gtest)
    target_compile_options(${owner} PRIVATE ${ISPH_TEST_OPTIMISATION})
    list(APPEND headers <gtest/gtest.h>)
  endif()
  if(kind STREQUAL "Library")
    set_target_properties(${owner} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  endif()
  target_precompile_headers(${owner} PRIVATE ${headers})
endfunction()

# Every library and executable with C++ sources defined under `dir` (recursively) reuses the
# precompiled header of its kind.
function(isph_precompile_headers dir)
  if(NOT ISPH_PRECOMPILED_HEADERS)
    return()
  endif()
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT type MATCHES "^(SHARED_LIBRARY|STATIC_LIBRARY|MODULE_LIBRARY|EXECUTABLE)$")
      continue()
    endif()
    get_target_property(sources ${target} SOURCES)
    list(FILTER sources INCLUDE REGEX "\\.cpp$")
    if(NOT sources)
      continue()
    endif()
    get_target_property(libs ${target} LINK_LIBRARIES)
    get_target_property(pic ${target} POSITION_INDEPENDENT_CODE)
    if(libs MATCHES "GTest::")
      set(kind Test)
    elseif(type MATCHES "^(SHARED|MODULE)_LIBRARY$" OR pic)
      set(kind Library)
    else()
      set(kind Executable)
    endif()
    isph_precompiled_header_owner(${kind})
    target_precompile_headers(${target} REUSE_FROM isphPrecompiled${kind})
    target_compile_options(${target} PRIVATE -Winvalid-pch)
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    isph_precompile_headers(${sub})
  endforeach()
endfunction()
