# The add-on zip an artist installs (scripts/make_package.py): built with everything else so
# the add-on tests install exactly what ships. `cmake --build build --target package_addon`.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
file(STRINGS ${PROJECT_SOURCE_DIR}/addon/blender_manifest.toml _manifest_version REGEX "^version *= *\"")
string(REGEX REPLACE "^version *= *\"([0-9.]+)\".*" "\\1" EDGELIGHT_ADDON_VERSION "${_manifest_version}")
set(EDGELIGHT_PACKAGE ${CMAKE_BINARY_DIR}/edgelight-${EDGELIGHT_ADDON_VERSION}-linux-x64.zip)
file(GLOB_RECURSE _package_sources CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/addon/*.py ${PROJECT_SOURCE_DIR}/addon/*.toml ${PROJECT_SOURCE_DIR}/shaders/*)
add_custom_command(OUTPUT ${EDGELIGHT_PACKAGE}
  COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/scripts/make_package.py
          ${PROJECT_SOURCE_DIR} $<TARGET_FILE:edgelight> ${EDGELIGHT_PACKAGE}
  DEPENDS edgelight ${_package_sources} ${PROJECT_SOURCE_DIR}/scripts/make_package.py
  COMMENT "Packaging the add-on: ${EDGELIGHT_PACKAGE}")
add_custom_target(package_addon ALL DEPENDS ${EDGELIGHT_PACKAGE})
