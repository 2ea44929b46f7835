#pragma once
// The names of a run file's `# key: value` metadata and footer lines. They are a file format
// (scripts read them), so every writer and reader spells them from here.

#include <QString>

namespace nb::key {

// Written before the header: what the run was.
inline const QString protocol = QStringLiteral("protocol");
inline const QString motion = QStringLiteral("motion");  // linear | sine
inline const QString velocity_mm_s = QStringLiteral("velocity_mm_s");
inline const QString depth_mm = QStringLiteral("depth_mm");
inline const QString amplitude_mm = QStringLiteral("amplitude_mm");
inline const QString centre_mm = QStringLiteral("centre_mm");
inline const QString frequency_hz = QStringLiteral("frequency_hz");
inline const QString cycles = QStringLiteral("cycles");
inline const QString tissue = QStringLiteral("tissue");
inline const QString tip = QStringLiteral("tip");
inline const QString seed = QStringLiteral("seed");
inline const QString thickness_mm = QStringLiteral("thickness_mm");
inline const QString bone_depth_mm = QStringLiteral("bone_depth_mm");
inline const QString clock = QStringLiteral("clock");
inline const QString organ = QStringLiteral("organ");
inline const QString specimen = QStringLiteral("specimen");
inline const QString operatorName = QStringLiteral("operator");
inline const QString session = QStringLiteral("session");
inline const QString notes = QStringLiteral("notes");
// Written by the acquisition engine.
inline const QString rate_hz = QStringLiteral("rate_hz");
inline const QString device = QStringLiteral("device");
inline const QString calibration = QStringLiteral("calibration");
inline const QString slope_V_per_g = QStringLiteral("slope_V_per_g");
inline const QString bias_V = QStringLiteral("bias_V");
inline const QString force_limit_N = QStringLiteral("force_limit_N");
inline const QString withdraw_force_limit_N = QStringLiteral("withdraw_force_limit_N");
inline const QString run_start_device_time_s = QStringLiteral("run_start_device_time_s");
inline const QString position_source = QStringLiteral("position_source");
// Video.
inline const QString video_file = QStringLiteral("video_file");
inline const QString video_fps = QStringLiteral("video_fps");
inline const QString sync_offset_s = QStringLiteral("sync_offset_s");
inline const QString sync_method = QStringLiteral("sync_method");
inline const QString sync_confidence = QStringLiteral("sync_confidence");
// The footer, written when the recording ends.
inline const QString end_reason = QStringLiteral("end_reason");
inline const QString samples = QStringLiteral("samples");
inline const QString dropped = QStringLiteral("dropped");
inline const QString sensor_gaps = QStringLiteral("sensor_gaps");
inline const QString ring_overruns = QStringLiteral("ring_overruns");
inline const QString late_periods = QStringLiteral("late_periods");
inline const QString fault = QStringLiteral("fault");
inline const QString emergency_stop = QStringLiteral("emergency_stop");
inline const QString force_limit_tripped_s = QStringLiteral("force_limit_tripped_s");
inline const QString force_limit_force_N = QStringLiteral("force_limit_force_N");
inline const QString force_limit_position_mm = QStringLiteral("force_limit_position_mm");
// "true" when the limit tripped on a reading at the end of the sensor's input range.
inline const QString force_over_range = QStringLiteral("force_over_range");
inline const QString write_error = QStringLiteral("write_error");
inline const QString recovered_rows = QStringLiteral("recovered_rows");
inline const QString recovered_at = QStringLiteral("recovered_at");

}  // namespace nb::key
