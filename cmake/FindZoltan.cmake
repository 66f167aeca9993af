# FindZoltan: Zoltan from Debian's libtrilinos-zoltan-dev (headers in /usr/include/trilinos).
# Defines Zoltan_FOUND, Zoltan_INCLUDE_DIR, Zoltan_LIBRARY and the imported target
# Zoltan::Zoltan (with MPI::MPI_C: zoltan.h includes mpi.h). Not the package's own
# ZoltanConfig.cmake: its target names the static scotch libraries of libscotch-dev, which
# libtrilinos-zoltan-dev does not install (the shared library finds its scotch by itself).
find_path(Zoltan_INCLUDE_DIR zoltan.h PATH_SUFFIXES trilinos)
find_library(Zoltan_LIBRARY NAMES trilinos_zoltan zoltan)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Zoltan REQUIRED_VARS Zoltan_LIBRARY Zoltan_INCLUDE_DIR)

if(Zoltan_FOUND AND NOT TARGET Zoltan::Zoltan)
  find_package(MPI REQUIRED COMPONENTS C)
  add_library(Zoltan::Zoltan UNKNOWN IMPORTED)
  set_target_properties(Zoltan::Zoltan PROPERTIES
    IMPORTED_LOCATION "${Zoltan_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${Zoltan_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES MPI::MPI_C)
endif()
mark_as_advanced(Zoltan_INCLUDE_DIR Zoltan_LIBRARY)
