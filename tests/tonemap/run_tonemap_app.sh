#!/bin/sh
# rtlab-tonemap end to end: a 2x1 PFM (grey 1 and grey 100, little-endian floats) is mapped with every
# operator to a PNG; a missing input must fail with status 1 and name the file.
set -eu
app=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
one='\000\000\200\077'
hundred='\000\000\310\102'
printf "PF\n2 1\n-1.0\n$one$one$one$hundred$hundred$hundred" > "$work/in.pfm"
for op in ward reinhard exposure aces; do
  "$app" "$work/in.pfm" -o "$work/$op.png" --op "$op" > "$work/$op.txt"
  test -s "$work/$op.png"
  grep -q "log-average luminance" "$work/$op.txt"
done
grep -q "log-average luminance 10" "$work/reinhard.txt"   # exp((ln 1 + ln 100) / 2) = 10
if "$app" "$work/missing.pfm" -o "$work/x.png" --op ward 2> "$work/err.txt"; then
  echo "a missing input must fail"; exit 1
fi
grep -q "missing.pfm" "$work/err.txt"
if "$app" "$work/in.pfm" -o "$work/x.png" --op drago 2> "$work/err2.txt"; then
  echo "an unknown operator must fail"; exit 1
fi
grep -q "ward" "$work/err2.txt"
echo "rtlab-tonemap: all checks passed"
