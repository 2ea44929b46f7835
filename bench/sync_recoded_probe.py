#!/usr/bin/python3
"""Measures `needlebench sync` on the simulator's own imaging video, coded again as a lab's might be.

Each case draws a simulated run with its rendered video (friction sines at 0.2-0.8 Hz or linear
insertions at 2-6 mm/s, liver 7, offsets 0.2-6 s), then codes the video again through the ffmpeg
tool in one of five looks: as rendered; H.264 with B-frames; faint and noisy H.264; faint and noisy
MPEG-4 part 2; noisy MJPEG (contrast 0.15-0.4, noise 3-10, quantiser and CRF drawn at random). The
seed is printed; each case prints the sync's error in frames against the offset the simulator used.
"""
import argparse
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from probe_support import add_common_arguments, chosen_seed  # noqa: E402

LOOKS = [
    ('rendered', None),
    ('h264', '-c:v libx264 -bf 3 -crf {crf} -pix_fmt yuv420p'),
    ('h264 faint', '-vf eq=contrast={c},noise=alls={nz}:allf=t -c:v libx264 -bf 2 -crf {crf} -pix_fmt yuv420p'),
    ('mpeg4 faint', '-vf eq=contrast={c},noise=alls={nz}:allf=t -c:v mpeg4 -q:v {q}'),
    ('mjpeg noisy', '-vf noise=alls={nz}:allf=t -c:v mjpeg -q:v {q}'),
]
FRAME_RATE = 30000 / 1001  # the simulator's imaging view


def draw(rng):
    friction = rng.random() < 2 / 3
    look, args = rng.choice(LOOKS)
    return dict(friction=friction, frequency=rng.choice([0.2, 0.3, 0.5, 0.8]), velocity=rng.choice([2, 4, 6]),
                offset=round(rng.uniform(0.2, 6.0), 3), seed=rng.randint(1, 999), look=look, args=args,
                c=round(rng.uniform(0.15, 0.4), 2), nz=rng.randint(3, 10), q=rng.randint(4, 10), crf=rng.randint(24, 32))


def describe(c):
    motion = f"sine {c['frequency']} Hz" if c['friction'] else f"linear {c['velocity']} mm/s"
    coding = '' if c['args'] is None else ' ' + c['args'].format(**c)
    return f"{motion}, offset {c['offset']} s, seed {c['seed']}, {c['look']}:{coding}"


def run_case(i, c, exe, root):
    d = os.path.join(root, f"case{i}")
    os.makedirs(d, exist_ok=True)
    run, rendered = os.path.join(d, 'run.csv'), os.path.join(d, 'rendered.avi')
    motion = (['--protocol', 'friction', '--cycles', '4', '--frequency-hz', str(c['frequency'])] if c['friction']
              else ['--protocol', 'stiffness', '--velocity-mm-s', str(c['velocity'])])
    subprocess.run([exe, 'simulate', '--overwrite', '--tissue', 'liver7', '--seed', str(c['seed']), '--out', run, '--video', rendered,
                    '--video-offset-s', str(c['offset'])] + motion, check=True, capture_output=True)
    video = rendered
    if c['args'] is not None:
        video = os.path.join(d, 'coded.mp4' if 'libx264' in c['args'] else 'coded.avi')
        subprocess.run(['ffmpeg', '-y', '-loglevel', 'error', '-i', rendered] + c['args'].format(**c).split() + [video], check=True)
    r = subprocess.run([exe, 'sync', run, video, '--json'], capture_output=True, text=True)
    try:
        j = json.loads(r.stdout)
    except ValueError:
        return None, r.stderr.strip()[:300]
    return dict(error=(j['offset_s'] - c['offset']) * FRAME_RATE, confidence=j['confidence'], acceptable=j['acceptable']), ''


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    add_common_arguments(ap)
    a = ap.parse_args()
    seed = chosen_seed(a, 'sync_recoded_probe')
    print(f"sync_recoded_probe: seed {seed} (rerun with --seed {seed}), {a.cases} cases", flush=True)
    rng = random.Random(seed)
    cases = [draw(rng) for _ in range(a.cases)]
    wanted = {int(i) for i in a.only.split(',')} if a.only else None
    root = a.keep or tempfile.mkdtemp(prefix='sync_recoded_')
    within = accepted = accepted_misses = 0
    counted = 0
    try:
        for i, c in enumerate(cases):
            if wanted is not None and i not in wanted:
                continue
            counted += 1
            o, problem = run_case(i, c, a.exe, root)
            if o is None:
                print(f"{i:3d}  sync refused: {problem}  {describe(c)}", flush=True)
                continue
            ok = abs(o['error']) <= 1.0
            within += ok
            accepted += ok and o['acceptable']
            accepted_misses += (not ok) and o['acceptable']
            print(f"{i:3d}  err {o['error']:+8.2f} fr  conf {o['confidence']:.2f}{'  ACCEPTED MISS' if not ok and o['acceptable'] else ''}  {describe(c)}",
                  flush=True)
    finally:
        if not a.keep:
            shutil.rmtree(root, ignore_errors=True)
    print(f"sync recoded probe: {counted} cases: within 1 frame {within}, of them accepted {accepted}; accepted misses {accepted_misses}")
    return 0


if __name__ == '__main__':
    sys.exit(main())
