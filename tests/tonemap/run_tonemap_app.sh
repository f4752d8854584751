#!/bin/sh
# rtlab-tonemap end to end: a 2x1 PFM (grey 1 and grey 100, little-endian floats) is mapped with every
# operator to a PNG, an EXR (when blender-data is installed) with one; a missing input must fail with status 1 and name the file, a bad flag with status 2 (the
# exit statuses of every rtlab app).
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
grep -q "reinhard: key 0.18, " "$work/reinhard.txt"        # the float parameter in its shortest form
# OpenEXR input (a DWAB-compressed studio map of blender-data, when installed).
exr=/usr/share/blender/datafiles/studiolights/world/studio.exr
if [ -f "$exr" ]; then
  "$app" "$exr" -o "$work/studio.png" --op reinhard > "$work/exr.txt"
  grep -q "studio.exr: 1024x512, log-average luminance" "$work/exr.txt"
fi
status=0
"$app" "$work/missing.pfm" -o "$work/x.png" --op ward 2> "$work/err.txt" || status=$?
[ "$status" = 1 ] || { echo "a missing input must fail with status 1, not $status"; exit 1; }
grep -q "^rtlab-tonemap: .*missing.pfm" "$work/err.txt"
status=0
"$app" "$work/in.pfm" -o "$work/x.png" --op drago 2> "$work/err2.txt" || status=$?
[ "$status" = 2 ] || { echo "an unknown operator must fail with status 2, not $status"; exit 1; }
grep -q "^rtlab-tonemap: --op: 'drago' is not one of aces, exposure, reinhard, ward$" "$work/err2.txt"
status=0
"$app" "$work/in.pfm" -o "$work/x.png" --kye 0.2 2> "$work/err3.txt" || status=$?
[ "$status" = 2 ] || { echo "an unknown flag must fail with status 2, not $status"; exit 1; }
grep -q "^rtlab-tonemap: unknown option '--kye'; did you mean '--key'?$" "$work/err3.txt"
echo "rtlab-tonemap: all checks passed"
