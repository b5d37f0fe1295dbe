# FindGiNaC
# ---------
# Finds GiNaC (and its dependency CLN) through pkg-config and provides the
# imported target GiNaC::GiNaC.  Sets GiNaC_FOUND and GiNaC_VERSION.

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

if(GiNaC_FOUND AND NOT TARGET GiNaC::GiNaC)
  add_library(GiNaC::GiNaC INTERFACE IMPORTED)
  if(TARGET PkgConfig::GINAC_PC)
    target_link_libraries(GiNaC::GiNaC INTERFACE PkgConfig::GINAC_PC)
  else()
    target_include_directories(GiNaC::GiNaC INTERFACE ${GiNaC_INCLUDE_DIR})
    target_link_libraries(GiNaC::GiNaC INTERFACE ${GiNaC_LIBRARY} ${CLN_LIBRARY})
  endif()
endif()

mark_as_advanced(GiNaC_INCLUDE_DIR GiNaC_LIBRARY CLN_LIBRARY)
