#!/usr/bin/env bash
# Esc as an operator presses it: the real `needlebench` window under Xvfb (1366x768), keys sent
# by xdotool through the X server (offscreen QTest skips the window system). Prepares the rig
# by keyboard, starts a run, opens the quit confirmation, presses Esc, and checks the run file
# says emergency_stop and the window is still there. Also Ctrl+N mid-run must not switch the
# session. Exit 77 (skipped) where xvfb-run or xdotool is missing.
#
# usage: xdotool_estop.sh NEEDLEBENCH_EXE [en|de] [SCREENSHOT_DIR]
set -u

if [ "${1:-}" = "--inner" ]; then
  set -e
  work=$NB_WORK
  export XDG_CONFIG_HOME=$work/config XDG_DATA_HOME=$work/data XDG_CACHE_HOME=$work/cache
  export NEEDLEBENCH_SESSION_DIR=$work/session
  unset QT_QPA_PLATFORM QT_QPA_PLATFORMTHEME
  if [ "$NB_LANG" = de ]; then export LC_ALL=de_DE.UTF-8 LANG=de_DE.UTF-8 LANGUAGE=de; else export LC_ALL=C.UTF-8 LANG=C.UTF-8; fi
  "$NB_EXE" >"$work/needlebench.log" 2>&1 &
  pid=$!
  trap 'kill $pid 2>/dev/null || true' EXIT
  win=$(timeout 30 xdotool search --sync --onlyvisible --name NeedleBench | head -1)
  [ -n "$win" ] || { echo "FAIL: no NeedleBench window"; exit 1; }
  xdotool windowmove "$win" 0 0 windowsize "$win" 1366 768
  xdotool windowfocus --sync "$win" || true
  sleep 3
  shot() { [ -z "$NB_SHOTS" ] || import -window root "$NB_SHOTS/$1_$NB_LANG.png"; }
  key() { xdotool key --clearmodifiers "$@"; sleep 0.8; }
  key alt+e                      # Enable stage
  if [ "$NB_LANG" = de ]; then key alt+b alt+t; else key alt+b; fi   # Bias (1 s to average)
  sleep 1.2
  if [ "$NB_LANG" = de ]; then key alt+z alt+n; else key alt+z; fi   # Zero
  if [ "$NB_LANG" = de ]; then key alt+k; else key alt+c; fi         # Calibration menu
  key n                          # ▸ the sensor's nominal calibration
  sleep 0.5
  key alt+i                      # Start insertion (4 mm/s to 30 mm: 7.5 s)
  sleep 1.5
  ls "$work/session"/run_*.csv >/dev/null 2>&1 || { echo "FAIL: the run did not start"; cat "$work/needlebench.log"; exit 1; }
  key ctrl+n                     # refused: a run is recording
  shot refused_mode_switch
  key ctrl+q                     # the quit confirmation opens (the run records)
  key Escape                     # the emergency stop, with the question open
  sleep 1
  shot latched_with_question
  key Escape                     # at rest: Esc closes the question (= do not quit)
  sleep 0.5
  shot latched
  kill -0 $pid || { echo "FAIL: the window quit"; exit 1; }
  run=$(ls "$work/session"/run_*.csv | head -1)
  reason=$(sed -n 's/^# end_reason: //p' "$run" | tail -1)
  echo "run file $(basename "$run"): end_reason=$reason"
  [ "$reason" = emergency_stop ] || { echo "FAIL: expected emergency_stop"; cat "$work/needlebench.log"; exit 1; }
  [ "$(ls -d "$work"/data/*/*/sessions/* 2>/dev/null | wc -l)" = 0 ] || { echo "FAIL: Ctrl+N made a session mid-run"; exit 1; }

  # Again with a menu open (a menu grabs the keyboard under X): reset on purpose, zero in tissue on
  # purpose (the override), start, menu, Esc.
  xdotool windowfocus --sync "$win" || true   # no window manager gives the focus back
  key alt+e                      # Enable stage: the deliberate reset of the latch
  sleep 0.5
  if [ "$NB_LANG" = de ]; then key alt+n; else key alt+z; fi         # Zero again (enabling lost it): in tissue, so it asks
  sleep 0.5
  if [ "$NB_LANG" = de ]; then key alt+a alt+t; else key alt+a; fi   # "Zero anyway"
  xdotool windowfocus --sync "$win" || true
  sleep 0.5
  key alt+i                      # the second run
  sleep 1.5
  [ "$(ls "$work/session"/run_*.csv | wc -l)" = 2 ] || { echo "FAIL: the second run did not start"; exit 1; }
  key alt+s                      # the Session menu opens (Sitzung: also S)
  shot menu_open
  key Escape                     # stops; the menu stays
  sleep 1
  key Escape                     # at rest: closes the menu
  run=$(ls "$work/session"/run_*.csv | sed -n 2p)
  reason=$(sed -n 's/^# end_reason: //p' "$run" | tail -1)
  echo "run file $(basename "$run") (Esc in a menu): end_reason=$reason"
  [ "$reason" = emergency_stop ] || { echo "FAIL: expected emergency_stop"; cat "$work/needlebench.log"; exit 1; }
  kill -0 $pid || { echo "FAIL: the window quit"; exit 1; }
  echo "PASS"
  exit 0
fi

exe=${1:?usage: xdotool_estop.sh NEEDLEBENCH_EXE [en|de] [SCREENSHOT_DIR]}
for tool in xvfb-run xdotool; do
  command -v "$tool" >/dev/null || { echo "skipped: $tool is missing (scripts/install-deps.sh installs it)"; exit 77; }
done
shots=${3:-}
if [ -n "$shots" ]; then
  command -v import >/dev/null || { echo "skipped: import (imagemagick) is missing"; exit 77; }
  mkdir -p "$shots"
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
NB_EXE=$exe NB_WORK=$work NB_LANG=${2:-en} NB_SHOTS=$shots \
  xvfb-run -a -s "-screen 0 1366x768x24" bash "$0" --inner
