#!/usr/bin/env python3
"""Sync on videos the project's renderer did not make.

Each case is drawn at random from the printed seed: a run from `needlebench simulate`
(sine 0.1-1 Hz or linear 1-10 mm/s), and a video of it drawn here with numpy and encoded
with the ffmpeg tool: a needle as a smooth profile sliding along its axis at any angle, on
static grain (4 px, 25 grey levels) with noise 3-35 and contrast 25-100, 15/25/29.97/30
frames/s, 320x240 to 1024x768, H.264 (B-frames), MJPEG or MPEG-4, with or without a burnt-in
frame counter and clock, offset -5..15 s, drift 0-0.2 %. `needlebench sync --json` is asked
for the offset and drift; the error is the largest over the recording, in frames. A case whose
video shows no motion (it starts after a short stroke has ended) has no right offset: it is
counted apart, and only a refusal or a confidence below the accept threshold is right for it.

  bench/sync_probe_matrix.py [--seed N] [--cases 16] [--only 3,7] [--expect-hits] [--exe build/app/needlebench] [--keep DIR]
                             [--slow-small | --bold] [--expect-honest] [--damage] [--operator] [--recode] [--coded-once]

--damage overwrites each video's packets over a stretch of 0.2-1.5 s drawn from the case's
seed (a bad copy, a bad sector): the frames there cannot be decoded, and the sync must still
hold on the frames either side.

--operator syncs as an operator who marks the picture: the needle's true line (drawn from the
shaft towards the tip) and a box around the needle's path, leaving out the burnt-in text beside it.

--recode codes each video again as H.264, as a lab converting a console's export does (x264
preset ultrafast to slow and CRF 18-28, drawn from the case's seed): two coders' lags add up.

--coded-once syncs as an operator who says each video is as its coder wrote it (sync
--coded-once): an H.264 file's lag is then known as its own coder's, not anywhere down to a
first coder's. With --recode that is untrue, and the probe shows what believing it costs.

--slow-small draws the family the main draw meets rarely: two cycles of a slow, short sine
(0.1-0.3 Hz, ±2.5-4 mm at 3-4 px/mm, so ±8-16 px), a faint needle (contrast 28-45, noise
4-12) in a 320x240 or 640x480 picture, always with the counter and the clock.

--bold draws the same slow, short sines with a bold needle on a quiet camera (contrast 60-150,
noise 2-8), as a metal needle under CT-fluoro shows: a coder that drops the quiet camera's
noise may still hold back the bold tip's slow motion (MPEG-4 showed it 0.2 to 1.6 frames late).

Needs python3-numpy (with python3-pandas) and ffmpeg; 16 cases take about 3 minutes on 2 cores.
"""
import argparse
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile

from concurrent.futures import ThreadPoolExecutor
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from probe_support import add_common_arguments, chosen_seed  # noqa: E402

try:
    import numpy as np
except ImportError:
    sys.exit("sync_probe_matrix: needs numpy (Debian: python3-numpy)")


def read_run(path):
    t, x = [], []
    with open(path) as f:
        header = None
        for line in f:
            if line.startswith('#'):
                continue
            cells = line.rstrip('\n').split(',')
            if header is None:
                header = cells
                it, ix = header.index('time_s'), header.index('position_mm')
                continue
            t.append(float(cells[it]))
            x.append(float(cells[ix]))
    return np.array(t), np.array(x)


def scene(c):
    """What draw_video draws before its noise: the random stream (the noise follows the
    background in it), the static background, and each pixel's place along and across the
    needle's axis, in pixels from the picture's centre."""
    rng = np.random.default_rng(c['seed'])
    W, H = c['size']
    u = np.array([np.cos(np.radians(c['angle'])), np.sin(np.radians(c['angle']))])
    grain = rng.normal(0, 1, (H // 4 + 2, W // 4 + 2))
    background = 110 + 25 * np.kron(grain, np.ones((4, 4)))[:H, :W]
    yy, xx = np.mgrid[0:H, 0:W].astype(np.float32)
    along = (xx - W / 2) * u[0] + (yy - H / 2) * u[1]
    across = -(xx - W / 2) * u[1] + (yy - H / 2) * u[0]
    return rng, background, along, across


def needle(c, along, across, tip):
    """The needle's brightness over the background with its tip at `tip` px along the axis."""
    shaft = c['contrast'] * np.exp(-0.5 * (across / 1.5) ** 2)
    return shaft * (1.0 / (1.0 + np.exp(np.clip(along - tip, -50, 50))))


def tip_px(c, t, x, k):
    """Where frame k (video time k/fps) draws the tip: it shows recording time (k/fps)(1 + drift) - offset."""
    return -40 + np.interp(np.asarray(k) / c['fps'] * (1 + c['drift']) - c['offset'], t, x) * c['px_per_mm']


def overlaid(c):
    """Where draw_video's burnt-in counter (top left) and clock (bottom right) can cover the picture."""
    W, H = c['size']
    yy, xx = np.mgrid[0:H, 0:W]
    if not c['counter']:
        return np.zeros((H, W), bool)
    return ((yy < 45) & (xx < 120)) | ((yy > H - 45) & (xx > W - 210))


def sync_error_frames(c, j, tr):
    """How many frames late `sync --json`'s answer j places recording times tr against the truth."""
    # video time = (1 + drift)·t + offset (the tool's mapping)
    truth = (tr + c['offset']) / (1 + c['drift'])
    return ((1 + j['drift']) * tr + j['offset_s'] - truth) * c['fps']


def draw_video(c, t, x, path, x264_preset):
    W, H = c['size']
    fps = c['fps']
    n = int((c['offset'] + t[-1] + 1.0) * fps)
    rng, background, along, across = scene(c)
    cmd = ['ffmpeg', '-y', '-loglevel', 'error', '-f', 'rawvideo', '-pix_fmt', 'gray', '-s', f'{W}x{H}', '-r', str(fps), '-i', '-']
    if c['counter']:
        cmd += ['-vf', "drawtext=text='%{n}':x=10:y=10:fontsize=24:fontcolor=white:box=1:boxcolor=black,"
                       "drawtext=text='%{pts\\:hms}':x=W-200:y=H-40:fontsize=20:fontcolor=white"]
    cmd += {'libx264': ['-c:v', 'libx264', '-preset', x264_preset, '-bf', '2', '-pix_fmt', 'yuv420p', '-crf', '23'],
            'mjpeg': ['-c:v', 'mjpeg', '-q:v', '5', '-pix_fmt', 'yuvj420p'],
            'mpeg4': ['-c:v', 'mpeg4', '-q:v', '5']}[c['codec']] + [path]
    p = subprocess.Popen(cmd, stdin=subprocess.PIPE)
    for k in range(n):
        img = background + needle(c, along, across, tip_px(c, t, x, k)) + rng.normal(0, c['noise'], (H, W))
        raw = np.clip(img, 0, 255).astype(np.uint8)
        if k == 0 and raw.tobytes()[:3] == b'ID3':
            # ffmpeg would read the frames as an ID3 tag and skip as many bytes as it says
            raw.flat[0] += 1
        p.stdin.write(raw.tobytes())
    p.stdin.close()
    if p.wait() != 0:
        raise RuntimeError('ffmpeg failed')


def damage_video(c, path):
    """Overwrites the packets of a stretch of the video (drawn from the case's seed) with noise;
    returns the stretch's (start, end) in video time."""
    rnd = random.Random(c['seed'] * 7 + 3)
    probe = subprocess.run(['ffprobe', '-v', 'error', '-select_streams', 'v:0', '-show_entries', 'packet=pts_time,dts_time,pos,size',
                            '-of', 'csv=p=0', path], capture_output=True, text=True, check=True)
    packets = []
    for line in probe.stdout.split():
        cells = line.split(',')
        if len(cells) < 4:
            continue
        pts, dts, size, pos = cells[:4]
        at = pts if pts not in ('', 'N/A') else dts
        if at in ('', 'N/A') or pos in ('', 'N/A'):
            continue
        packets.append((float(at), int(pos), int(size)))
    if not packets:
        raise RuntimeError(f'ffprobe placed no packet of {path}: nothing to damage')
    end = max(p[0] for p in packets)
    length = rnd.uniform(0.2, 1.5)
    start = rnd.uniform(0.1 * end, max(0.1 * end, 0.9 * end - length))
    with open(path, 'r+b') as f:
        for at, pos, size in packets:
            if start <= at < start + length and size > 16:
                f.seek(pos + 8)
                f.write(bytes(rnd.randrange(256) for _ in range(size - 8)))
    return start, start + length


def recode_video(c, path):
    """Codes the video again as H.264 (B-frames), as a lab converting a console's export might:
    x264 preset and CRF drawn from the case's seed. Returns the new file's path."""
    rnd = random.Random(c['seed'] * 11 + 5)
    c['recoded'] = (rnd.choice(['ultrafast', 'superfast', 'veryfast', 'faster', 'fast', 'medium', 'slow']), rnd.randint(18, 28))
    out = os.path.splitext(path)[0] + '_recoded.mp4'
    subprocess.run(['ffmpeg', '-y', '-loglevel', 'error', '-i', path, '-c:v', 'libx264', '-preset', c['recoded'][0], '-crf',
                    str(c['recoded'][1]), '-bf', '2', '-pix_fmt', 'yuv420p', out], check=True)
    return out


def draw_cases(seed, count):
    rnd = random.Random(seed)
    cases = []
    for i in range(count):
        linear = rnd.random() < 0.3
        c = dict(i=i, linear=linear, frequency=round(rnd.uniform(0.1, 1.0), 2), amplitude=round(rnd.uniform(3, 10), 1),
                 velocity=round(rnd.uniform(1, 10), 1), offset=round(rnd.uniform(-5, 15), 3), drift=round(rnd.uniform(0, 0.002), 5),
                 fps=rnd.choice([25, 29.97, 30, 15]), size=rnd.choice([(640, 480), (320, 240), (1024, 768), (720, 576)]),
                 angle=round(rnd.uniform(-180, 180), 1), px_per_mm=round(rnd.uniform(3, 10), 1), noise=round(rnd.uniform(3, 35), 1),
                 contrast=round(rnd.uniform(25, 100)), codec=rnd.choice(['libx264', 'mjpeg', 'mpeg4']), counter=rnd.choice([0, 1]),
                 tissue=rnd.choice(['liver1', 'liver2', 'liver3', 'liver5', 'liver7']), seed=rnd.randrange(1, 99999))
        if linear:
            c['px_per_mm'] = min(c['px_per_mm'], 4.0)  # the whole stroke inside the picture
        cases.append(c)
    return cases


def draw_slow_small_cases(seed, count):
    rnd = random.Random(seed)
    cases = []
    for i in range(count):
        cases.append(dict(i=i, linear=False, frequency=round(rnd.uniform(0.1, 0.3), 2), amplitude=round(rnd.uniform(2.5, 4), 1),
                          velocity=1, offset=round(rnd.uniform(-4, 4), 3), drift=round(rnd.uniform(0, 0.002), 5),
                          fps=rnd.choice([15, 25, 29.97]), size=rnd.choice([(320, 240), (640, 480)]),
                          angle=round(rnd.uniform(-180, 180), 1), px_per_mm=round(rnd.uniform(3, 4), 1),
                          noise=round(rnd.uniform(4, 12), 1), contrast=round(rnd.uniform(28, 45)),
                          codec=rnd.choice(['mjpeg', 'libx264', 'mpeg4']), counter=1, tissue='liver7',
                          seed=rnd.randrange(1, 99999), cycles=2))
    return cases


def draw_slow_bold_cases(seed, count):
    """The slow, short sines of draw_slow_small_cases with a bold needle on a quiet camera
    (contrast 60-150, noise 2-8: a metal needle under CT-fluoro), drawn from a stream of their
    own so that the other families' cases stay as they are."""
    cases = draw_slow_small_cases(seed, count)
    rnd = random.Random(f'bold {seed}')
    for c in cases:
        c['contrast'] = round(rnd.uniform(60, 150))
        c['noise'] = round(rnd.uniform(2, 8), 1)
    return cases


def add_family_arguments(ap):
    """The options that choose which family of cases is drawn (one at most)."""
    family = ap.add_mutually_exclusive_group()
    family.add_argument('--slow-small', action='store_true', help='draw slow, short sines of a faint needle with overlays')
    family.add_argument('--bold', action='store_true',
                        help='draw the slow, short sines of --slow-small with a bold needle on a quiet camera (contrast 60-150, noise 2-8)')


def draw_family(a, seed, count):
    """The cases of the family the options ask for (--slow-small, --bold, or the main draw)."""
    if a.bold:
        return draw_slow_bold_cases(seed, count)
    return (draw_slow_small_cases if a.slow_small else draw_cases)(seed, count)


def family_options(a):
    """The options that redraw the same cases."""
    return (' --slow-small' if a.slow_small else '') + (' --bold' if a.bold else '')


def describe(c):
    motion = f"linear {c['velocity']} mm/s" if c['linear'] else f"sine {c['frequency']} Hz ±{c['amplitude']} mm"
    return (f"{motion}, offset {c['offset']} s, drift {100 * c['drift']:.3f} %, {c['fps']} fps {c['size'][0]}x{c['size'][1]}, "
            f"angle {c['angle']}, {c['px_per_mm']} px/mm, noise {c['noise']}, contrast {c['contrast']}, {c['codec']}"
            + (", counter and clock" if c['counter'] else "")
            + (f", recoded as H.264 {c['recoded'][0]} CRF {c['recoded'][1]}" if 'recoded' in c else "")
            + (f", damaged {c['damaged'][0]:.2f}-{c['damaged'][1]:.2f} s" if 'damaged' in c else ""))


def operator_marks(c, x):
    """What an operator marks on the picture: the needle's line (drawn from the shaft towards the
    tip) and a box around the needle's path, from 60 px of shaft behind the tip's furthest-back
    place to 30 px ahead of its furthest reach, 20 px either side, as one would draw it to leave
    out burnt-in text beside the path (text on the path stays in)."""
    W, H = c['size']
    u = np.array([np.cos(np.radians(c['angle'])), np.sin(np.radians(c['angle']))])
    centre = np.array([W / 2, H / 2])
    p1, p2 = centre - 50 * u, centre + 50 * u
    tips = -40 + np.array([x.min(), x.max()]) * c['px_per_mm']
    ends = np.array([centre + (tips[0] - 60) * u, centre + (tips[1] + 30) * u])
    lo = np.clip(np.floor(ends.min(axis=0) - 20), 0, [W - 1, H - 1]).astype(int)
    hi = np.clip(np.ceil(ends.max(axis=0) + 20), 0, [W, H]).astype(int)
    return ['--needle', ','.join(f'{v:.1f}' for v in (*p1, *p2)), '--roi', f'{lo[0]},{lo[1]},{hi[0] - lo[0]},{hi[1] - lo[1]}']


def make_case(c, exe, root, x264_preset, damage=False, recode=False):
    """Simulates the case's run and draws (and codes) its video under root/caseI; returns the
    run's path, the video's, and the run's time and position."""
    d = os.path.join(root, f"case{c['i']}")
    os.makedirs(d, exist_ok=True)
    if c['linear']:
        motion = ['--protocol', 'stiffness', '--velocity-mm-s', str(c['velocity']), '--depth-mm', str(min(40, c['velocity'] * 6))]
    else:
        motion = ['--protocol', 'friction', '--frequency-hz', str(c['frequency']), '--amplitude-mm', str(c['amplitude']),
                  '--cycles', str(c.get('cycles', max(2, min(6, int(12 * c['frequency'])))))]
    run = os.path.join(d, 'run.csv')
    subprocess.run([exe, 'simulate', '--overwrite', '--tissue', c['tissue'], '--seed', str(c['seed']), '--out', run] + motion,
                   check=True, capture_output=True)
    t, x = read_run(run)
    video = os.path.join(d, 'video.mp4' if c['codec'] == 'libx264' else 'video.avi')
    draw_video(c, t, x, video, x264_preset)
    if recode:
        video = recode_video(c, video)
    if damage:
        c['damaged'] = damage_video(c, video)
    return run, video, t, x


def run_case(c, exe, root, x264_preset, damage=False, operator=False, recode=False, coded_once=False):
    run, video, t, x = make_case(c, exe, root, x264_preset, damage, recode)
    # A video that starts after the motion has ended (a short stroke, an offset well below
    # zero) shows nothing to sync on: the honest answer is a refusal or a low confidence, and
    # no error in frames means anything.
    n = int((c['offset'] + t[-1] + 1.0) * c['fps'])
    seen = (t >= -c['offset'] / (1 + c['drift'])) & (t <= (n / c['fps'] - c['offset']) / (1 + c['drift']))
    moving = bool(seen.any()) and np.ptp(x[seen]) >= 0.05 * max(np.ptp(x), 1e-9)
    r = subprocess.run([exe, 'sync', run, video, '--json'] + (operator_marks(c, x) if operator else []) + (['--coded-once'] if coded_once else []),
                       capture_output=True, text=True)
    try:
        j = json.loads(r.stdout)
    except ValueError:
        return c, dict(refused=True, moving=moving), r.stderr.strip()[:300]
    if j['offset_s'] is None:  # nothing in the picture moved with the recording
        return c, dict(refused=True, moving=moving), 'no offset: nothing in the picture moved with the recording'
    err = sync_error_frames(c, j, np.linspace(0.0, t[-1], 100))
    return c, dict(error=float(err[np.argmax(np.abs(err))]), confidence=j['confidence'], acceptable=j['acceptable'],
                   threshold=j['accept_threshold'], moving=moving), ''


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[1])
    add_common_arguments(ap)
    add_family_arguments(ap)
    ap.add_argument('--damage', action='store_true', help="overwrite a stretch of each video's packets (0.2-1.5 s)")
    ap.add_argument('--operator', action='store_true',
                    help="sync as an operator who draws the needle's line and a box around its path")
    ap.add_argument('--recode', action='store_true',
                    help="code each video again as H.264 (x264 preset ultrafast-slow and CRF 18-28 drawn per case), as a lab's conversion does")
    ap.add_argument('--coded-once', action='store_true',
                    help="sync as an operator who says each video is as its coder wrote it (sync --coded-once); "
                         "with --recode that is not so, and the probe shows what believing it costs")
    ap.add_argument('--x264-preset', default='medium',
                    help="x264's preset for the H.264 videos (medium, x264's own default; veryfast codes a noisy "
                         "1024x768 picture four times faster, with the same two B-frames)")
    ap.add_argument('--expect-honest', action='store_true',
                    help='exit with status 1 if a case more than a frame off was offered for acceptance')
    ap.add_argument('--expect-hits', action='store_true',
                    help='exit with status 1 unless every case is within a frame and accepted (a regression check)')
    ap.add_argument('--expect-within', type=float, default=None, metavar='FRAMES',
                    help='exit with status 1 unless every case is within FRAMES frames, accepted or not')
    ap.add_argument('--share-index', type=int, default=None, metavar='I',
                    help="as a test, probe I of the suite's: runs only if I is in its share (NB_CASE_SHARE, tests/support/case_share.h)")
    a = ap.parse_args()
    if a.share_index is not None:
        share = 1 if os.environ.get('NB_ALL_CASES') else max(1, int(os.environ.get('NB_CASE_SHARE') or 1))
        if a.share_index % share:
            print(f"one sync probe in {share} runs here (NB_CASE_SHARE); scripts/test-all-cases.sh runs them all")
            return 77
    seed = chosen_seed(a, 'sync_probe_matrix')
    rerun = f"--seed {seed}{family_options(a)}{' --damage' if a.damage else ''}{' --operator' if a.operator else ''}{' --recode' if a.recode else ''}{' --coded-once' if a.coded_once else ''}"
    rerun += f" --x264-preset {a.x264_preset}" if a.x264_preset != 'medium' else ''
    print(f"sync_probe_matrix: seed {seed} (rerun with {rerun}), {a.cases} cases", flush=True)
    cases = draw_family(a, seed, a.cases)
    if a.only:
        wanted = {int(i) for i in a.only.split(',')}
        cases = [c for c in cases if c['i'] in wanted]
    root = a.keep or tempfile.mkdtemp(prefix='sync_probe_')
    within = accepted_within = misses = honest_misses = unsyncable = offered = 0
    worst = 0.0
    try:
        with ThreadPoolExecutor(2) as pool:
            for c, o, problem in pool.map(lambda c: run_case(c, a.exe, root, a.x264_preset, a.damage, a.operator, a.recode, a.coded_once), cases):
                if o.get('refused'):
                    if o['moving']:
                        misses += 1
                        honest_misses += 1
                        worst = float('inf')
                    else:
                        unsyncable += 1
                    print(f"{c['i']:3d}  sync refused: {problem}{'' if o['moving'] else ' (the video shows no motion)'}  {describe(c)}",
                          flush=True)
                    continue
                if not o['moving']:
                    unsyncable += 1
                    offered += o['acceptable']
                    print(f"{c['i']:3d}  the video shows no motion: conf {o['confidence']:.2f}"
                          f"{'  OFFERED FOR ACCEPTANCE' if o['acceptable'] else ''}  {describe(c)}", flush=True)
                    continue
                ok = abs(o['error']) <= 1.0
                worst = max(worst, abs(o['error']))
                within += ok
                accepted_within += ok and o['acceptable']
                if not ok:
                    misses += 1
                    honest_misses += not o['acceptable']
                print(f"{c['i']:3d}  err {o['error']:+8.2f} fr  conf {o['confidence']:.2f}{'  ACCEPTED MISS' if not ok and o['acceptable'] else ''}  {describe(c)}",
                      flush=True)
    finally:
        if not a.keep:
            shutil.rmtree(root, ignore_errors=True)
    print(f"sync probe: {len(cases)} cases: within 1 frame {within}, of them accepted {accepted_within}; "
          f"misses {misses}, of which below the accept threshold {honest_misses}; "
          f"{unsyncable} whose video shows no motion, {offered} of them offered for acceptance")
    if a.expect_honest and (honest_misses < misses or offered):
        print(f"sync probe: {misses - honest_misses + offered} misses offered for acceptance", file=sys.stderr)
        return 1
    if a.expect_within is not None and worst > a.expect_within:
        print(f"sync probe: a case {worst:.2f} frames off, more than {a.expect_within:g}", file=sys.stderr)
        return 1
    if a.expect_hits and accepted_within < len(cases) - unsyncable:
        print(f"sync probe: {len(cases) - unsyncable - accepted_within} of {len(cases) - unsyncable} cases not within a frame and accepted",
              file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
