# OMPL as the target ompl::ompl, which OMPL's CMake package defines since 1.7. Older OMPL (Debian's
# 1.5.2, 1.6) sets only OMPL_LIBRARIES and OMPL_INCLUDE_DIRS: the target is made here from them, so
# that our targets (and their installed exports) name OMPL the same way with every version.
# Included after find_package(ompl), by the project and by the installed ompl_core package.
if(NOT TARGET ompl::ompl)
  add_library(ompl::ompl INTERFACE IMPORTED)
  set_target_properties(ompl::ompl PROPERTIES
    INTERFACE_LINK_LIBRARIES "${OMPL_LIBRARIES}"
    INTERFACE_INCLUDE_DIRECTORIES "${OMPL_INCLUDE_DIRS}")
endif()
