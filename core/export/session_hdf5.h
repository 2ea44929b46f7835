#pragma once
// Per-session export: one HDF5 file readable without NeedleBench (h5py, MATLAB h5read, h5dump).
//
//   /                       attrs: format, version, session, the session metadata
//   /runs/<run>             attrs: every metadata field (a double when numeric, else a string)
//                                  plus `<field>_units` where the field's name carries a unit
//   /runs/<run>/time_s      1-D double datasets, attrs `units`, `description`
//   /runs/<run>/position_mm, velocity_mm_s, acceleration_mm_s2, force_N, other recorded columns
//   /runs/<run>/labels/     parallel 1-D columns of the label interval table: label, track,
//                           comment (variable-length UTF-8 strings), start_s, end_s, duration_s,
//                           peak_force_N, mean_force_N (double), start_frame, end_frame (int64)
//
// Only plain doubles, int64 and strings, so every HDF5 reader understands it.

#include "dataset.h"
#include "export_error.h"

namespace nb {

// Group name of a run inside /runs ('/' is not allowed in HDF5 names, '.' alone is reserved).
QString hdf5GroupName(const QString& runName);

// Writes the whole dataset through a temporary file renamed on success. Returns false when
// cancelled through `progress` (counted in runs). Throws ExportError.
bool writeSessionHdf5(const QString& path, const Dataset& dataset, const ExportProgress& progress = {});

}  // namespace nb
