# Generates version.cpp from `git describe` at build time, rewriting it only when the
# description changes, so the banner of every log names the exact source it ran.
set(ISPH_VERSION_CPP ${CMAKE_BINARY_DIR}/generated/version.cpp)
add_custom_target(isphGitVersion
  COMMAND ${CMAKE_COMMAND}
          -DSOURCE_DIR=${CMAKE_SOURCE_DIR}
          -DOUTPUT=${ISPH_VERSION_CPP}
          -DFALLBACK=${PROJECT_VERSION}
          -P ${CMAKE_SOURCE_DIR}/cmake/WriteVersion.cmake
  BYPRODUCTS ${ISPH_VERSION_CPP}
  COMMENT "Checking git version"
  VERBATIM)
