#!/usr/bin/env python3
"""How late the coded pictures themselves show the needle, beside the lag the sync takes off.

The sync (core/sync_displacement.cpp) takes off a coder's lag modelled from the pictures' noise
(core/picture_lag.h). Whether that model is right cannot be told from the sync's error alone:
the tracker and the fit add their own. This probe reads the lag in the pictures with no tracker.
Each case is drawn as bench/sync_probe_matrix.py draws it (same seed, same cases, the same
--slow-small and --recode). Every decoded picture is compared, along a band 4 px either side of
the needle's axis (the burnt-in counter and clock left out), with the needle as drawn on its
known background at tips 0.05 px apart; the best fit is where the picture shows the tip. The
picture's lag is the shift, in frames, that best fits those tips to the tips drawn.

Printed per case, in frames: the pictures' lag; the lag `needlebench sync --json` took off
(picture_lag_frames) and how far it says that may be off (picture_lag_uncertainty_frames); how
late the sync's offset was before it took that off (at the middle of the recording: the tracker's
and the fit's own share is the difference from the pictures' lag). Then the median and extremes
of what the model missed (pictures' lag less the model's), and in how many cases the miss was
within what the model said.

  bench/picture_lag_probe.py [--seed N] [--cases 16] [--only 3,7] [--slow-small | --bold] [--recode] [--coded-once] [--exe ...] [--keep DIR]

Needs python3-numpy and ffmpeg; 16 slow-small cases take about a minute on 2 cores.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

from concurrent.futures import ThreadPoolExecutor
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from probe_support import add_common_arguments, chosen_seed  # noqa: E402
import sync_probe_matrix as matrix  # noqa: E402

import numpy as np  # noqa: E402  (sync_probe_matrix has said so when it is missing)


def decoded_band(video, c, band):
    """The band's pixels of every decoded picture, one row a picture (read a picture at a time:
    a whole 1024x768 video held as floats would take gigabytes)."""
    W, H = c['size']
    p = subprocess.Popen(['ffmpeg', '-v', 'error', '-i', video, '-f', 'rawvideo', '-pix_fmt', 'gray', '-'], stdout=subprocess.PIPE)
    rows = []
    while (raw := p.stdout.read(W * H)) and len(raw) == W * H:
        rows.append(np.frombuffer(raw, np.uint8).reshape(H, W)[band].astype(np.float32))
    if p.wait() != 0:
        raise RuntimeError(f'ffmpeg could not decode {video}')
    return np.array(rows)


def shown_tips(c, video, drawn):
    """Where each picture of the video shows the tip, in px along the axis (as drawn: tip_px)."""
    _, background, along, across = matrix.scene(c)
    band = (np.abs(across) < 4) & (along > drawn.min() - 8) & (along < drawn.max() + 8) & ~matrix.overlaid(c)
    grid = np.arange(drawn.min() - 8, drawn.max() + 8, 0.05)
    models = np.array([matrix.needle(c, along[band], across[band], g) for g in grid])
    models -= models.mean(axis=1, keepdims=True)
    seen = decoded_band(video, c, band) - background[band]
    seen -= seen.mean(axis=1, keepdims=True)  # a coder's shift of the mean grey is no tip
    # |seen - model|² = |seen|² - 2 seen·model + |model|²: the first is the same for every tip
    cost = (models * models).sum(axis=1)[None, :] - 2.0 * seen @ models.T
    return grid[np.argmin(cost, axis=1)]


def lag_of(c, t, x, shown):
    """The shift in frames that best fits the tips shown to the tips drawn (where the tip moves)."""
    k = np.arange(len(shown))
    best, lag = np.inf, np.nan
    for shift in np.arange(-2.0, 6.0, 0.02):
        drawn = matrix.tip_px(c, t, x, k - shift)
        moving = np.abs(np.gradient(drawn)) > 0.02
        if moving.sum() < 10:
            continue
        # No offset of its own: the needle fitted is the needle drawn, and along a steady stroke
        # an offset is a shift in time.
        cost = np.mean((shown - drawn)[moving] ** 2)
        if cost < best:
            best, lag = cost, shift
    return lag


def probe(c, exe, root, recode, coded_once):
    run, video, t, x = matrix.make_case(c, exe, root, 'medium', recode=recode)
    frames = int((c['offset'] + t[-1] + 1.0) * c['fps'])  # as draw_video draws them
    pictures = lag_of(c, t, x, shown_tips(c, video, matrix.tip_px(c, t, x, np.arange(frames))))
    r = subprocess.run([exe, 'sync', run, video, '--json'] + (['--coded-once'] if coded_once else []), capture_output=True, text=True)
    try:
        j = json.loads(r.stdout)
    except ValueError:
        return c, pictures, None, None, None
    if j['offset_s'] is None:
        return c, pictures, None, None, None
    modelled = j.get('picture_lag_frames') or 0.0
    said = j.get('picture_lag_uncertainty_frames') or 0.0
    late = matrix.sync_error_frames(c, j, 0.5 * t[-1]) + modelled  # at the recording's middle
    return c, pictures, modelled, said, late


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    add_common_arguments(ap)
    matrix.add_family_arguments(ap)
    ap.add_argument('--recode', action='store_true', help='code each video again as H.264 (as sync_probe_matrix.py)')
    ap.add_argument('--coded-once', action='store_true', help='tell the sync each video was coded once (sync --coded-once)')
    a = ap.parse_args()
    seed = chosen_seed(a, 'picture_lag_probe')
    print(f"picture_lag_probe: seed {seed} (rerun with --seed {seed}{matrix.family_options(a)}"
          f"{' --recode' if a.recode else ''}{' --coded-once' if a.coded_once else ''}), {a.cases} cases", flush=True)
    cases = matrix.draw_family(a, seed, a.cases)
    if a.only:
        wanted = {int(i) for i in a.only.split(',')}
        cases = [c for c in cases if c['i'] in wanted]
    root = a.keep or tempfile.mkdtemp(prefix='picture_lag_probe_')
    missed, covered = [], 0
    try:
        with ThreadPoolExecutor(2) as pool:
            for c, pictures, modelled, said, late in pool.map(lambda c: probe(c, a.exe, root, a.recode, a.coded_once), cases):
                if modelled is None:
                    print(f"{c['i']:3d}  pictures {pictures:+5.2f} fr  sync refused  {matrix.describe(c)}", flush=True)
                    continue
                missed.append(pictures - modelled)
                covered += abs(pictures - modelled) <= said
                print(f"{c['i']:3d}  pictures {pictures:+5.2f} fr  modelled {modelled:5.2f} ± {said:4.2f}  sync before it {late:+5.2f}  "
                      f"missed {pictures - modelled:+5.2f}  {matrix.describe(c)}", flush=True)
    finally:
        if not a.keep:
            shutil.rmtree(root, ignore_errors=True)
    if missed:
        m = np.array(missed)
        print(f"picture lag probe: {len(m)} cases: the model missed the pictures' lag by median {np.median(m):+.2f} frames, "
              f"least {m.min():+.2f}, most {m.max():+.2f}; more than half a frame short in {int((m > 0.5).sum())}, "
              f"more than half a frame over in {int((m < -0.5).sum())}; within the uncertainty it gave in {covered}")
    return 0


if __name__ == '__main__':
    sys.exit(main())
