# The OMPL found by find_package(ompl): 1.5.2 (Debian bookworm) and 2.0.x are tested, 1.6 and 1.7
# build through the same version checks (ompl_core/compat/OmplVersions.h for the C++ side).
#   OMPL_MM_OMPL_MAJOR_MINOR  "1.5", "2.0", ...: what the installed packages record and require
#   OMPL_MM_HAVE_OMPL_OPENDE  whether OMPL still has its ODE extension (removed in OMPL 1.7.0)
if(OMPL_VERSION VERSION_LESS 1.5)
  message(FATAL_ERROR "OMPL ${OMPL_VERSION} found (ompl_DIR=${ompl_DIR}); this project needs OMPL 1.5 or newer. "
                      "Point CMAKE_PREFIX_PATH or ompl_DIR at a newer OMPL.")
endif()
string(REGEX MATCH "^[0-9]+\\.[0-9]+" OMPL_MM_OMPL_MAJOR_MINOR "${OMPL_VERSION}")
if(OMPL_VERSION VERSION_LESS 1.7)
  set(OMPL_MM_HAVE_OMPL_OPENDE ON)
else()
  set(OMPL_MM_HAVE_OMPL_OPENDE OFF)
endif()
include(${CMAKE_CURRENT_LIST_DIR}/OmplTarget.cmake)
message(STATUS "Building against OMPL ${OMPL_VERSION} (ompl_DIR=${ompl_DIR})")
