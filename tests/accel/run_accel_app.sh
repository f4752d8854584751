#!/bin/sh
# rtlab-accel end to end on a unit cube written here: every kd method and the baselines agree with brute
# force (CSV columns as FORMATS.md lists them, zero mismatches), the hit file has one record per ray, a
# one-ray file gives the expected hit, and a missing or malformed mesh or ray file fails with status 1
# and a message naming the file.
set -eu
app=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
cat > "$work/cube.obj" <<'OBJ'
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 3 2
f 1 4 3
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 2 3 7
f 2 7 6
f 3 4 8
f 3 8 7
f 4 1 5
f 4 5 8
OBJ
"$app" --mesh "$work/cube.obj" --method kd-sah --method kd-sah-binned --method kd-median --method kd-midpoint \
  --method kd-three-way --method bvh --method octree --method brute --rays random --random-count 3000 --sample 3000 \
  --runs 1 --threads 1 --csv "$work/out.csv" --hits-out "$work/hits.bin" > "$work/out.txt"
head -1 "$work/out.csv" | grep -q '^method,mesh,triangles,threads,build_s,nodes,leaves,empty_leaves,max_depth,mean_leaf_prims,bytes,sah_cost,ray_set,rays,closest_mrays_s,anyhit_mrays_s,mismatches'
test "$(tail -n +2 "$work/out.csv" | wc -l)" -eq 8
# Column 17: mismatches against brute force, which must be 0 for every method.
awk -F, 'NR > 1 && $17 != "0" { print "mismatches for " $1 ": " $17; bad = 1 } END { exit bad }' "$work/out.csv"
test "$(wc -c < "$work/hits.bin")" -eq $((16 + 16 * 3000))
# One ray from (0.5, 0.5, 5) straight down: the top face at t = 4 (little-endian float32 0x40800000).
half='\000\000\000\077'; five='\000\000\240\100'; zero='\000\000\000\000'; minus_one='\000\000\200\277'
inf='\000\000\200\177'
printf "RTRAYS01\001\000\000\000\000\000\000\000$half$half$five$zero$zero$minus_one$zero$inf" > "$work/one.rays"
"$app" --mesh "$work/cube.obj" --method kd-sah --rays "$work/one.rays" --runs 1 --hits-out "$work/one.hits" > /dev/null
test "$(od -An -tx1 -j16 -N4 "$work/one.hits" | tr -d ' \n')" = "00008040"
# Bad input: status 1 and the file named.
printf 'v 0 0 0\nv 1 0 0\nv nope 1 0\nf 1 2 3\n' > "$work/bad.obj"
printf 'RTRAYS01\001\000\000\000\000\000\000\000abc' > "$work/bad.rays"
for case in "--mesh $work/missing.obj:missing.obj" "--mesh $work/bad.obj:bad.obj" \
            "--mesh $work/cube.obj --rays $work/bad.rays:bad.rays" "--mesh $work/cube.obj --method kd-nope:kd-nope"; do
  args=${case%:*}
  name=${case##*:}
  status=0
  # shellcheck disable=SC2086
  "$app" $args --runs 1 > /dev/null 2> "$work/err.txt" || status=$?
  if [ "$status" -ne 1 ]; then echo "$args: exit status $status, expected 1"; exit 1; fi
  grep -q "$name" "$work/err.txt"
done
echo "rtlab-accel: all checks passed"
