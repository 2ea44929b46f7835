# Reads a NeedleBench session HDF5 with h5py (and an exported run CSV with pandas) the way a
# user's script would, and checks what issue 15 promises: strings, integers, units on every
# dataset, g and the force-from-voltage chain, a relative video link. Run by test_readers.
# Usage: python3 read_session_h5.py SESSION.h5 RUN.csv
import os, sys, h5py, numpy as np, pandas as pd
path = sys.argv[1]
f = h5py.File(path, 'r')
def text(v):
    return v.decode('utf-8') if isinstance(v, (bytes, np.bytes_)) else str(v)
assert text(f.attrs['format']) == 'needlebench-session'
assert abs(float(f.attrs['standard_gravity_m_s2']) - 9.81) < 1e-12
assert 'slope_V_per_g' in text(f.attrs['force_from_voltage'])
assert text(f.attrs['organ']) == 'nan', repr(f.attrs['organ'])
assert text(f.attrs['specimen']) == '0012', repr(f.attrs['specimen'])
assert text(f.attrs['operator']) == 'Zoë'
run = f['runs/run_001']
assert run.attrs['samples'].dtype.kind == 'i'
assert run['seq'].dtype == np.int64, run['seq'].dtype
assert run['labels/start_frame'].dtype == np.int64
missing = []
f.visititems(lambda n, o: missing.append(n) if isinstance(o, h5py.Dataset) and 'units' not in o.attrs else None)
assert not missing, missing
labels = [text(x) for x in run['labels/label'][()]]
assert labels == ['a', 'b1'], labels
assert [text(x) for x in run['labels/comment'][()]] == ['', "Zoë's note"]
video = os.path.join(os.path.dirname(path), text(run.attrs['video']))
assert os.path.isfile(video), video
# force from voltage with the stated chain
g = float(f.attrs['standard_gravity_m_s2'])
v = run['voltage_V'][()]; F = run['force_N'][()]
rebuilt = (v - float(run.attrs['bias_V'])) * g / (1000 * float(run.attrs['slope_V_per_g']))
assert np.nanmax(np.abs(rebuilt - F)) < 1e-3, np.nanmax(np.abs(rebuilt - F))
csv = pd.read_csv(sys.argv[2], comment='#')
assert csv['seq'].dtype == np.int64, csv['seq'].dtype
print('h5py-ok', len(run['force_N']))
