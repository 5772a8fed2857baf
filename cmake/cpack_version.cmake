# CPACK_PROJECT_CONFIG_FILE: read by cpack when it packages, so the package's version is the
# tree's as last built (cmake/git_description.cmake writes it at every build), not as it was at
# the last configure.
include("${CPACK_ACCELCAL_VERSION_FILE}")
set(CPACK_PACKAGE_VERSION "${ACCELCAL_PACKAGE_VERSION}")
set(CPACK_DEBIAN_PACKAGE_VERSION "${ACCELCAL_PACKAGE_VERSION}")
