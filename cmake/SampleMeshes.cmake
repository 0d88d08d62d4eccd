# Classic meshes from Debian's libcgal-demo (data.tar.gz), extracted once into the build tree
# for tests, benchmarks and the main job. EDGELIGHT_MESH_DIR points at them.
set(EDGELIGHT_CGAL_DATA "/usr/share/doc/libcgal-dev/data.tar.gz" CACHE FILEPATH "libcgal-demo data set")
set(EDGELIGHT_MESH_DIR "${CMAKE_BINARY_DIR}/meshes")
# joint, pinion and anchor: the ground truth's parts (bench/gt_scenes.py), which tests open too.
set(_el_meshes cow.off fandisk.off bunny00.off armadillo.off cube.off joint.off pinion.off anchor.off)
# Each mesh a build tree lacks is extracted, so a tree made before a mesh was added gets it.
set(_members "")
foreach(m ${_el_meshes})
  if(NOT EXISTS "${EDGELIGHT_MESH_DIR}/${m}")
    list(APPEND _members "data/meshes/${m}")
  endif()
endforeach()
if(EXISTS "${EDGELIGHT_CGAL_DATA}" AND _members)
  file(MAKE_DIRECTORY "${EDGELIGHT_MESH_DIR}")
  execute_process(
    COMMAND tar xzf "${EDGELIGHT_CGAL_DATA}" --strip-components=2 -C "${EDGELIGHT_MESH_DIR}" ${_members}
    RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(WARNING "could not extract sample meshes from ${EDGELIGHT_CGAL_DATA}")
  endif()
endif()
if(NOT EXISTS "${EDGELIGHT_MESH_DIR}/cow.off")
  message(WARNING "libcgal-demo meshes not found (apt-get install libcgal-demo): mesh tests will fail")
endif()
