# FindGiNaC
# ---------
# Finds GiNaC (and its dependency CLN) through pkg-config and provides the
# imported target GiNaC::GiNaC.  Sets GiNaC_FOUND and GiNaC_VERSION.
#
# With ALEMBERT_REPRODUCIBLE_ORDER set, GiNaC::GiNaC links the static archives of GiNaC
# and CLN (libginac.a, libcln.a, then GMP) instead of the shared libraries.  GiNaC orders
# the terms of sums and products by hash values seeded with the address of its type
# names; in a shared library that address moves with address-space randomisation, so
# the same program would order terms, and round, differently from run to run.  Linked
# into a position-dependent executable the address is fixed (see CMakeLists.txt).

find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(GINAC_PC QUIET IMPORTED_TARGET ginac)
endif()

find_path(GiNaC_INCLUDE_DIR ginac/ginac.h HINTS ${GINAC_PC_INCLUDE_DIRS})
find_library(GiNaC_LIBRARY NAMES ginac HINTS ${GINAC_PC_LIBRARY_DIRS})
find_library(CLN_LIBRARY NAMES cln HINTS ${GINAC_PC_LIBRARY_DIRS})
set(GiNaC_VERSION ${GINAC_PC_VERSION})

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(GiNaC
  REQUIRED_VARS GiNaC_LIBRARY CLN_LIBRARY GiNaC_INCLUDE_DIR
  VERSION_VAR GiNaC_VERSION)

if(ALEMBERT_REPRODUCIBLE_ORDER)
  find_library(GiNaC_STATIC_LIBRARY NAMES libginac.a HINTS ${GINAC_PC_LIBRARY_DIRS})
  find_library(CLN_STATIC_LIBRARY NAMES libcln.a HINTS ${GINAC_PC_LIBRARY_DIRS})
  find_library(GMP_LIBRARY NAMES gmp)
  mark_as_advanced(GiNaC_STATIC_LIBRARY CLN_STATIC_LIBRARY GMP_LIBRARY)
  if(NOT GiNaC_STATIC_LIBRARY OR NOT CLN_STATIC_LIBRARY OR NOT GMP_LIBRARY)
    message(FATAL_ERROR "ALEMBERT_REPRODUCIBLE_ORDER needs the static libraries libginac.a "
                        "and libcln.a (Debian: libginac-dev, libcln-dev) and GMP; install them "
                        "or configure with -DALEMBERT_REPRODUCIBLE_ORDER=OFF")
  endif()
endif()

if(GiNaC_FOUND AND NOT TARGET GiNaC::GiNaC)
  add_library(GiNaC::GiNaC INTERFACE IMPORTED)
  if(ALEMBERT_REPRODUCIBLE_ORDER)
    target_include_directories(GiNaC::GiNaC INTERFACE ${GiNaC_INCLUDE_DIR})
    target_link_libraries(GiNaC::GiNaC INTERFACE ${GiNaC_STATIC_LIBRARY} ${CLN_STATIC_LIBRARY}
                                                 ${GMP_LIBRARY})
  elseif(TARGET PkgConfig::GINAC_PC)
    target_link_libraries(GiNaC::GiNaC INTERFACE PkgConfig::GINAC_PC)
  else()
    target_include_directories(GiNaC::GiNaC INTERFACE ${GiNaC_INCLUDE_DIR})
    target_link_libraries(GiNaC::GiNaC INTERFACE ${GiNaC_LIBRARY} ${CLN_LIBRARY})
  endif()
endif()

mark_as_advanced(GiNaC_INCLUDE_DIR GiNaC_LIBRARY CLN_LIBRARY)
