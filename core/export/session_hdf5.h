#pragma once
// Per-session export: one HDF5 file readable without NeedleBench (Octave load, MATLAB h5read,
// h5py, h5dump).
//
//   /                       attrs: format, version, session, the session metadata,
//                                  standard_gravity_m_s2 and force_from_voltage (the chain
//                                  from voltage_V to force_N)
//   /runs/<run>             attrs: every metadata field (int64 or double when written as a
//                                  number, else a string: "nan" and text fields stay text)
//                                  plus `<field>_units` where the field's name carries a unit;
//                                  source / video: relative to this file when beside or below
//                                  it, else absolute (*_absolute: always absolute)
//   /runs/<run>/time_s      1-D double datasets, attrs `units`, `description`
//   /runs/<run>/position_mm, velocity_mm_s, acceleration_mm_s2, force_N, other recorded columns
//                           (seq as int64, units "1")
//   /runs/<run>/labels/     parallel 1-D columns of the label interval table: label, track,
//                           comment (fixed-length strings, UTF-8 bytes), start_s, end_s, duration_s,
//                           peak_force_N, mean_force_N (double), start_frame, end_frame (int64,
//                           only when the run has a video); every dataset has `units`
//
// Only plain doubles, int64 and fixed-length strings, so every HDF5 reader understands it.
// Built in memory and written in one go through NAME.part (locked while written; a stale
// one is removed by the next export).

#include "dataset.h"
#include "export_error.h"

namespace nb {

// Group name of a run inside /runs ('/' is not allowed in HDF5 names, '.' alone is reserved).
QString hdf5GroupName(const QString& runName);

// Writes the whole dataset through a temporary file renamed on success. Returns false when
// cancelled through `progress` (counted in runs). Throws ExportError.
bool writeSessionHdf5(const QString& path, const Dataset& dataset, const ExportProgress& progress = {});

}  // namespace nb
