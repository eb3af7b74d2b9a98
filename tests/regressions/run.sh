#!/usr/bin/env bash
# Runs the command-line inputs of issue 9 (the regression table of
# docs/robustness.md) against a slider-crank binary, each in a scratch
# directory under `ulimit -v 4000000` and `timeout 10`, and prints one
# tab-separated line per command: point, command, exit (or "killed by
# signal N", "timed out"), seconds, peak memory, standard output's bytes,
# whether it held inf or NaN or claimed a dead centre, standard error's
# first line.
#
#   tests/regressions/run.sh path/to/slider-crank
#
# Devices and links are the scratch directory's own: `full` (a device
# node like /dev/full, made with mknod when run as root, because a version
# that replaced devices would otherwise replace the system's), `stdout` (a
# link to /dev/stdout) and `link.svg` (a link to real.svg).
set -uo pipefail
bin=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
header="curve,tolerance_px,method,steps,segments,measured_error_px,time_us,timed_by"
printf '%s\npolar,1e-1,cubic,,10,5e-324,10.4,criterion\npolar,1e-2,cubic,,16,2.3e-3,24.8,criterion\n' "$header" > tiny.csv
printf 'angle,force\n40,1e308\n50,-1e308\n60,3\n' > big.csv
printf '[page]\nwidth = 20000\nheight = 20000\n' > huge-page.toml
printf 'angle = 45\nlayers = ["mechanism", "velocity", "torque"]\ntorque = 1e308\n[mechanism]\ncrank = 1e-100\nrod = 3e-100\n' > huge-torque.toml
printf 'old' > real.svg
ln -s real.svg link.svg
ln -s /dev/stdout stdout
if [ "$(id -u)" = 0 ]; then mknod full c 1 7; fi

# Time and peak memory where GNU time is installed.
timer=()
if [ -x /usr/bin/time ]; then timer=(/usr/bin/time -f '%e %M' -o time.txt); fi

while IFS=$'\t' read -r point command flag; do
  [ -z "$point" ] && continue
  case "$point" in \#*) continue ;; esac
  # A row marked long takes more than the 10 s a row is given (a million
  # angles of JSON): its test is named in the table instead.
  if [ "${flag:-}" = long ]; then
    printf '%s\t%s\tskipped: long (see its test)\n' "$point" "$command"
    continue
  fi
  if [[ "$command" == *" full"* && ! -c full ]]; then
    printf '%s\t%s\tskipped: no device node (not root)\n' "$point" "$command"
    continue
  fi
  run=${command/slider-crank/$bin}
  : > out.bin; : > err.txt
  echo "? 0" > time.txt
  ( ulimit -v 4000000
    "${timer[@]}" timeout 10 bash -c "$run" > out.bin 2> err.txt ) 2>/dev/null
  code=$?
  read -r secs kb < <(tail -1 time.txt)
  case $code in
    124) status="timed out" ;;
    0|1|2) status="exit $code" ;;
    *) if [ $code -gt 128 ]; then status="killed by signal $((code - 128))"; else status="exit $code"; fi ;;
  esac
  if grep -q "Command terminated by signal" time.txt 2>/dev/null; then
    status="killed ($(head -1 time.txt))"
  fi
  bytes=$(stat -c %s out.bin)
  nonfinite=$(grep -aoiwE 'inf|nan' out.bin | sort -u | tr '\n' ' ')
  # A dead centre claimed in what was printed (text or a figure's notes).
  said=$(head -c 1000000 out.bin | sed 's/<[^>]*>//g' | grep -aoE 'unbounded \(dead centre[^)]*\)|dead centre:[^.]*' | head -1)
  first=$(head -c 4000 err.txt | head -1)
  printf '%s\t%s\t%s\t%s s\t%s MB\t%s B%s%s\t%s\n' "$point" "$command" "$status" "$secs" \
    "$((${kb:-0} / 1024))" "$bytes" "${nonfinite:+ (holds $nonfinite)}" "${said:+ (says \"$said\")}" "$first"
  rm -f f.svg page.png
done < "$here/commands.tsv"
# What the runs did to the files they were given.
printf 'files\tlink.svg\t%s\n' "$(if [ -L link.svg ]; then echo "still a link; real.svg starts $(head -c 4 real.svg)"; else echo "replaced by a regular file; real.svg starts $(head -c 4 real.svg)"; fi)"
printf 'files\tstdout\t%s\n' "$(if [ -L stdout ]; then echo "still a link"; else echo "replaced by a regular file"; fi)"
if [ "$(id -u)" = 0 ]; then
  printf 'files\tfull\t%s\n' "$(if [ -c full ]; then echo "still a device"; else echo "replaced by a regular file of $(stat -c %s full) bytes"; fi)"
fi
