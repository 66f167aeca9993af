# FindHYPRE: the hypre library (Debian's libhypre-dev puts headers in /usr/include/hypre).
# Defines HYPRE_FOUND, HYPRE_INCLUDE_DIR, HYPRE_LIBRARY, HYPRE_VERSION and the imported
# target HYPRE::HYPRE, which carries MPI::MPI_C (hypre's headers include mpi.h).
find_path(HYPRE_INCLUDE_DIR HYPRE.h PATH_SUFFIXES hypre)
find_library(HYPRE_LIBRARY HYPRE)

if(HYPRE_INCLUDE_DIR AND EXISTS "${HYPRE_INCLUDE_DIR}/HYPRE_config.h")
  file(STRINGS "${HYPRE_INCLUDE_DIR}/HYPRE_config.h" _hypreVersionLine
       REGEX "^#define HYPRE_RELEASE_VERSION \"[0-9.]+\"")
  string(REGEX REPLACE ".*\"([0-9.]+)\".*" "\\1" HYPRE_VERSION "${_hypreVersionLine}")
  unset(_hypreVersionLine)
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(HYPRE
  REQUIRED_VARS HYPRE_LIBRARY HYPRE_INCLUDE_DIR
  VERSION_VAR HYPRE_VERSION)

if(HYPRE_FOUND AND NOT TARGET HYPRE::HYPRE)
  find_package(MPI REQUIRED COMPONENTS C)
  add_library(HYPRE::HYPRE UNKNOWN IMPORTED)
  set_target_properties(HYPRE::HYPRE PROPERTIES
    IMPORTED_LOCATION "${HYPRE_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${HYPRE_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES MPI::MPI_C)
endif()
mark_as_advanced(HYPRE_INCLUDE_DIR HYPRE_LIBRARY)
