"""What the sync probes share: their common options and the check that they can run."""
import os
import random
import shutil
import sys


def add_common_arguments(ap):
    ap.add_argument('--seed', type=int, default=None)
    ap.add_argument('--cases', type=int, default=16)
    ap.add_argument('--exe', default=os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'build', 'app', 'needlebench'))
    ap.add_argument('--keep', default=None, help='keep each case (run, videos) under this folder')
    ap.add_argument('--only', default=None, help="run only these cases of the seed's draw (comma-separated numbers)")


def cannot_run(exe):
    """Why a probe cannot run with `exe` (an empty string when it can)."""
    if not (os.path.isfile(exe) and os.access(exe, os.X_OK)):
        return f"{exe} is not an executable needlebench (give --exe)"
    if not shutil.which('ffmpeg'):
        return "the ffmpeg tool is needed"
    return ''


def chosen_seed(a, name):
    """The seed asked for, or one drawn now; exits with status 2 when the probe cannot run."""
    problem = cannot_run(a.exe)
    if problem:
        print(f"{name}: {problem}", file=sys.stderr)
        sys.exit(2)
    return a.seed if a.seed is not None else random.randrange(100000, 1000000)
