# The installed programs and Python modules find the libraries they were linked with outside the
# system's folders (an OMPL of one's own, such as OMPL 2 in a prefix) without LD_LIBRARY_PATH.
# Included after OmplVersion.cmake (which makes ompl::ompl), before any target.
set(CMAKE_INSTALL_RPATH_USE_LINK_PATH ON)
# CMake leaves folders inside the source tree out of that run path, and scripts/build-with-ompl2.sh
# keeps its OMPL there (build-ompl2/): OMPL's folder is added by hand.
get_target_property(ompl_target_type ompl::ompl TYPE)
if(ompl_target_type STREQUAL "INTERFACE_LIBRARY")
  list(GET OMPL_LIBRARIES 0 ompl_library)  # the target made by OmplTarget.cmake
else()
  get_target_property(ompl_library ompl::ompl LOCATION)
endif()
get_filename_component(ompl_library_dir "${ompl_library}" DIRECTORY)
if(ompl_library_dir AND NOT ompl_library_dir IN_LIST CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES)
  list(APPEND CMAKE_INSTALL_RPATH "${ompl_library_dir}")
endif()
