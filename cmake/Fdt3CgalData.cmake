# CGAL's example surfaces (elephant.off, bunny00.off, fandisk.off, ...) for the mesher's data test and benchmark.
# Debian's libcgal-demo ships them only inside data.tar.gz; the few used here are extracted into the build tree at
# configure time. FDT3_CGAL_DATA_DIR names that folder; when the archive is absent the folder stays empty and the
# test and the benchmark say which file is missing.
set(FDT3_CGAL_DATA_ARCHIVE "/usr/share/doc/libcgal-dev/data.tar.gz" CACHE FILEPATH
    "CGAL's data archive (Debian: libcgal-demo)")
set(FDT3_CGAL_DATA_DIR "${CMAKE_BINARY_DIR}/cgal_data/data/meshes")
set(_fdt3_cgal_meshes elephant fandisk bunny00 anchor_dense joint couplingdown refined_elephant)
if(EXISTS "${FDT3_CGAL_DATA_ARCHIVE}" AND CMAKE_VERSION VERSION_LESS 3.18)
  message(STATUS "CMake ${CMAKE_VERSION} cannot extract CGAL's data (3.18 can): the mesher's CGAL-data test skips")
elseif(EXISTS "${FDT3_CGAL_DATA_ARCHIVE}")
  set(_fdt3_missing OFF)
  foreach(_mesh ${_fdt3_cgal_meshes})
    if(NOT EXISTS "${FDT3_CGAL_DATA_DIR}/${_mesh}.off")
      set(_fdt3_missing ON)
    endif()
  endforeach()
  if(_fdt3_missing)
    set(_fdt3_patterns)
    foreach(_mesh ${_fdt3_cgal_meshes})
      list(APPEND _fdt3_patterns "data/meshes/${_mesh}.off")
    endforeach()
    file(ARCHIVE_EXTRACT INPUT "${FDT3_CGAL_DATA_ARCHIVE}" DESTINATION "${CMAKE_BINARY_DIR}/cgal_data"
         PATTERNS ${_fdt3_patterns})
  endif()
  message(STATUS "CGAL data surfaces from ${FDT3_CGAL_DATA_ARCHIVE} in ${FDT3_CGAL_DATA_DIR}")
else()
  message(STATUS "CGAL's data archive not found (apt install libcgal-demo): the mesher's CGAL-data test skips, "
                 "the mesher benchmark runs on the fibre cube alone")
endif()
