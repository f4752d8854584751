#!/bin/sh
# rtlab-accel end to end on a unit cube written here: every kd method and the baselines agree with brute
# force (CSV columns as FORMATS.md lists them, zero mismatches), the hit file has one record per ray, a
# one-ray file gives the expected hit, rays spawned from the cube's top face (--spawn) leave it outwards
# and cross to the bottom inwards, and a missing or malformed mesh, ray or spawn file fails with status 1
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
# Two rays starting at (0.25, 0.75, 1) on triangle 3 of the top face, up and down: spawned, the upward one
# leaves the cube (a miss), the downward one crosses it to triangle 1 of the bottom face at t just below 1
# (its origin moved into the cube by the offset, where the ray as given would meet the bottom at 1).
quarter='\000\000\200\076'; three_quarters='\000\000\100\077'; one='\000\000\200\077'
printf "RTRAYS01\002\000\000\000\000\000\000\000$quarter$three_quarters$one$zero$zero$one$zero$inf$quarter$three_quarters$one$zero$zero$minus_one$zero$inf" > "$work/top.rays"
printf 'RTSPAWN1\002\000\000\000\000\000\000\000\003\000\000\000\003\000\000\000' > "$work/top.spawn"
"$app" --mesh "$work/cube.obj" --method kd-sah --method bvh --rays "$work/top.rays" --spawn "$work/top.spawn" --runs 1 \
  --hits-out "$work/top.hits" > "$work/top.txt"
grep -q '^spawned rays, kd-sah: 1 outward, 0 hit their own triangle again; 1 inward, 0 missed$' "$work/top.txt"
grep -q '^spawned rays, bvh: 1 outward, 0 hit their own triangle again; 1 inward, 0 missed$' "$work/top.txt"
test "$(od -An -tx1 -j20 -N4 "$work/top.hits" | tr -d ' \n')" = "ffffffff"
test "$(od -An -tx1 -j36 -N4 "$work/top.hits" | tr -d ' \n')" = "01000000"
od -An -tf4 -j32 -N4 "$work/top.hits" | awk '{ exit !($1 > 0.999 && $1 < 1) }'
# --packets: primary tiles and shadow rays, singly and in packets; the kd-tree's packets answer as its single
# rays, bit for bit, and so do bvh's (one ray at a time behind the packet call).
"$app" --mesh "$work/cube.obj" --method kd-sah --method bvh --packets --primary-size 16 --runs 1 --threads 1 \
  > "$work/packets.txt"
test "$(grep -c 'packets differ from single rays (bit for bit) on 0 closest-hit and 0 any-hit answers' \
  "$work/packets.txt")" -eq 4
grep -q '^kd-sah 4x2 ' "$work/packets.txt"
printf 'RTSPAWN1\001\000\000\000\000\000\000\000\003\000\000\000' > "$work/count.spawn"
printf 'RTSPAWN1\002\000\000\000\000\000\000\000\003\000\000\000\014\000\000\000' > "$work/range.spawn"
# Bad input: status 1 and the file named.
printf 'v 0 0 0\nv 1 0 0\nv nope 1 0\nf 1 2 3\n' > "$work/bad.obj"
printf 'RTRAYS01\001\000\000\000\000\000\000\000abc' > "$work/bad.rays"
for case in "--mesh $work/missing.obj:missing.obj" "--mesh $work/bad.obj:bad.obj" \
            "--mesh $work/cube.obj --rays $work/bad.rays:bad.rays" "--mesh $work/cube.obj --method kd-nope:kd-nope" \
            "--mesh $work/cube.obj --rays $work/top.rays --spawn $work/count.spawn:count.spawn" \
            "--mesh $work/cube.obj --rays $work/top.rays --spawn $work/range.spawn:range.spawn" \
            "--mesh $work/cube.obj --rays $work/top.rays --spawn $work/bad.rays:bad.rays" \
            "--mesh $work/cube.obj --rays random --spawn $work/top.spawn:top.spawn" \
            "--mesh $work/cube.obj --packets --rays random:--packets" \
            "--mesh $work/cube.obj --packets --primary-size 18:--primary-size 18"; do
  args=${case%:*}
  name=${case##*:}
  status=0
  # shellcheck disable=SC2086
  "$app" $args --runs 1 > /dev/null 2> "$work/err.txt" || status=$?
  if [ "$status" -ne 1 ]; then echo "$args: exit status $status, expected 1"; exit 1; fi
  grep -q -e "$name" "$work/err.txt"
done
echo "rtlab-accel: all checks passed"
