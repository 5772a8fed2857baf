# Sources compiled on their own in a unity build (ACCELCAL_UNITY): their file-local helpers
# (anonymous namespaces) share a name with a neighbour's. Renaming the helpers or moving a shared
# one into its layer takes a file off this list.
set(_accelcal_unity_alone
  src/accelcal/acquire/capture_engine/static_stability.cpp
  src/accelcal/acquire/capture_engine/turntable_stability.cpp
  src/accelcal/analysis/allan_deviation.cpp
  src/accelcal/analysis/allan_confidence.cpp
  src/accelcal/io/export/c_header.cpp
  src/accelcal/io/export/px4_params.cpp
  src/accelcal/report/report_html.cpp
  src/accelcal/report/report_text.cpp
  src/accelcal/session/detail/record_rows.cpp
  src/accelcal/calibration/diagnosis/residual_structure.cpp
  src/accelcal/calibration/diagnosis/sensor_effects.cpp
  src/accelcal/io/export/calibration_csv.cpp
  tests/unit/calibration/magnitude_fit_limits_test.cpp
  tests/unit/acquire/orientation_check_test.cpp
  tests/unit/session/session_store_test.cpp
  tests/unit/acquire/turntable_stability_test.cpp
  tests/unit/app/wizard_record_test.cpp
  tests/unit/acquire/spike_reason_test.cpp
  tests/unit/io/capture_set_writer_test.cpp
  src/accelcal/app/wizard/resume_summary.cpp
  tests/unit/app/leveling_test.cpp
  tests/unit/app/wizard_engine_test.cpp
  tests/unit/app/wizard_level_offset_test.cpp
  tests/unit/app/wizard_redo_test.cpp
  tests/unit/app/wizard_resume_summary_test.cpp
  tests/unit/app/certificate_test.cpp
  tests/unit/app/wizard_checks_test.cpp
  tests/physics/apply_check.cpp
  bench/capture_engine_bench.cpp
)
# Source file properties belong to a directory: set them where the targets using the files live.
set(_accelcal_unity_dirs ${CMAKE_SOURCE_DIR})
if(ACCELCAL_BUILD_TESTS)
  list(APPEND _accelcal_unity_dirs ${CMAKE_SOURCE_DIR}/tests)
endif()
if(ACCELCAL_BUILD_BENCH)
  list(APPEND _accelcal_unity_dirs ${CMAKE_SOURCE_DIR}/bench)
endif()
foreach(_file IN LISTS _accelcal_unity_alone)
  set_source_files_properties(${CMAKE_SOURCE_DIR}/${_file} DIRECTORY ${_accelcal_unity_dirs}
                              PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
endforeach()
