#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# End-to-end tests of the `exactmesh` command on the fixtures in tests/data.
# Usage: cli_test.sh <exactmesh binary> <tests/data dir> <scratch dir> <case>
set -uo pipefail

exactmesh=$1
data=$2
work=$3
case_name=$4
rm -rf "$work" && mkdir -p "$work" || exit 1

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# run <expected status> <args...>: runs exactmesh, keeps stdout/stderr in $work/out, $work/err.
run() {
  local expected=$1
  shift
  "$exactmesh" "$@" >"$work/out" 2>"$work/err"
  local status=$?
  if [[ $status -ne $expected ]]; then
    fail "exactmesh $* exited $status, expected $expected; stdout: $(cat "$work/out"); stderr: $(cat "$work/err")"
    return 1
  fi
  return 0
}

# expect_error <status> <pattern> <args...>: exactly one stderr line, starting with
# "exactmesh: error: " and matching the extended regex <pattern>; nothing else, no trace.
expect_error() {
  local status=$1 pattern=$2
  shift 2
  run "$status" "$@" || return
  local lines
  lines=$(wc -l <"$work/err")
  if [[ $lines -ne 1 ]]; then
    fail "exactmesh $*: expected one stderr line, got $lines: $(cat "$work/err")"
  elif ! grep -Eq "^exactmesh: error: " "$work/err"; then
    fail "exactmesh $*: stderr does not start with 'exactmesh: error: ': $(cat "$work/err")"
  elif ! grep -Eq -- "$pattern" "$work/err"; then
    fail "exactmesh $*: stderr does not match /$pattern/: $(cat "$work/err")"
  fi
}

triangulate_all_algorithms() {
  local node algorithm order base
  for node in square_with_center one_based_comments duplicates kite; do
    for algorithm in bowyer-watson green-sibson tanemura-merriam; do
      for order in given random brio; do
        base="$work/$node.$algorithm.$order"
        run 0 triangulate "$data/$node.node" -o "$base.ele" --algorithm "$algorithm" \
          --order "$order" --seed 3 || continue
        [[ -s "$base.ele" ]] || fail "$base.ele missing"
        [[ -s "$base.neigh" ]] || fail "$base.neigh missing"
        run 0 check "$data/$node.node" "$base.ele" &&
          grep -Eq '^ok: [0-9]+ triangles, exact Delaunay$' "$work/out" ||
          fail "check did not accept $base.ele: $(cat "$work/out")"
      done
    done
  done
  # Triangle counts: 4 around the centre; 6 for the 1-based file; duplicates are not vertices.
  head -n1 "$work/square_with_center.bowyer-watson.brio.ele" | grep -q '^4 3 0$' ||
    fail "square_with_center: expected 4 triangles"
  head -n1 "$work/one_based_comments.green-sibson.given.ele" | grep -q '^6 3 0$' ||
    fail "one_based_comments: expected 6 triangles"
  # 1-based input gives 1-based output: triangle 1 first, vertex numbers in 1..6, never 0.
  sed -n 2p "$work/one_based_comments.bowyer-watson.brio.ele" | grep -q '^1 ' ||
    fail "one_based_comments: first triangle is not numbered 1"
  if awk 'NR > 1 && ($2 < 1 || $3 < 1 || $4 < 1 || $2 > 6 || $3 > 6 || $4 > 6)' \
    "$work/one_based_comments.tanemura-merriam.random.ele" | grep -q .; then
    fail "one_based_comments: vertex numbers outside 1..6"
  fi
  # Duplicates (vertices 5 and 6 repeat 1 and 4) never appear; 4 triangles.
  head -n1 "$work/duplicates.bowyer-watson.brio.ele" | grep -q '^4 3 0$' ||
    fail "duplicates: expected 4 triangles"
  if awk 'NR > 1 && ($2 == 5 || $3 == 5 || $4 == 5 || $2 == 6 || $3 == 6 || $4 == 6)' \
    "$work/duplicates.green-sibson.random.ele" | grep -q .; then
    fail "duplicates: a repeated point is used instead of its first occurrence"
  fi
  # .neigh: same count, -1 on the hull; the square has 4 hull edges.
  head -n1 "$work/square_with_center.tanemura-merriam.given.neigh" | grep -q '^4 3$' ||
    fail "square_with_center.neigh header"
  [[ $(tail -n +2 "$work/square_with_center.tanemura-merriam.given.neigh" | grep -o -- '-1' | wc -l) -eq 4 ]] ||
    fail "square_with_center.neigh: expected 4 hull sides"
}

# expect_msh <file.msh> <block regex> <what>: a Gmsh 4.1 ASCII file with the element block.
expect_msh() {
  [[ $(head -n2 "$1" | tail -n1) == "4.1 0 8" ]] || fail "msh header"
  grep -q "$2" "$1" || fail "msh: $3"
}

# expect_vtu <file.vtu> <counts>: a closed VTK XML file whose piece has these counts.
expect_vtu() {
  grep -q "$2" "$1" || fail "vtu counts"
  grep -q '</VTKFile>' "$1" || fail "vtu not closed"
}

output_formats() {
  run 0 triangulate "$data/square_with_center.node" -o "$work/square.msh" || return
  expect_msh "$work/square.msh" '^2 1 2 4$' "no block of 4 triangles (type 2)"
  run 0 triangulate "$data/one_based_comments.node" -o "$work/ob.vtu" --algorithm green-sibson
  expect_vtu "$work/ob.vtu" 'NumberOfPoints="6" NumberOfCells="6"'
  run 0 triangulate "$data/duplicates.node" -o "$work/dup.svg" --algorithm tanemura-merriam
  grep -q '<svg xmlns="http://www.w3.org/2000/svg"' "$work/dup.svg" || fail "svg header"
  grep -q '</svg>' "$work/dup.svg" || fail "svg not closed"
  # Upper-case extensions work; unknown ones are bad usage (exit 2) and write nothing.
  run 0 triangulate "$data/kite.node" -o "$work/kite.ELE" && [[ -s "$work/kite.neigh" ]] ||
    fail "upper-case .ELE"
  expect_error 2 "unsupported output extension '\.off'" triangulate "$data/kite.node" -o "$work/kite.off"
  [[ ! -e "$work/kite.off" ]] || fail "kite.off written despite the error"
}

# expect_stats <points> <predicate> <counters...>: the --stats output in $work/out has a
# 'construct_seconds: T' line, a 'name: N' line for each counter, 'points: <points>', the stage
# counters of <predicate> (or 'compiled out'), and only 'name: value' lines.
expect_stats() {
  local points=$1 predicate=$2 name
  shift 2
  grep -Eq '^construct_seconds: [0-9]+\.[0-9]+$' "$work/out" ||
    fail "--stats: no 'construct_seconds: T' line: $(cat "$work/out")"
  for name in "$@"; do
    grep -Eq "^$name: [0-9]+$" "$work/out" || fail "--stats: no '$name: N' line"
  done
  grep -q "^points: $points\$" "$work/out" || fail "--stats: points is not $points"
  grep -Eq "^($predicate\\.calls: [0-9]+|predicate_stages: compiled out.*)\$" "$work/out" ||
    fail "--stats: neither $predicate stage counters nor 'compiled out'"
  if grep -Ev '^[a-z0-9_.]+: ' "$work/out" | grep -q .; then
    fail "--stats: a line is not 'name: value': $(grep -Ev '^[a-z0-9_.]+: ' "$work/out")"
  fi
}

stats() {
  run 0 triangulate "$data/square_with_center.node" -o "$work/s.ele" --stats || return
  expect_stats 5 orient2d points duplicates orient_calls incircle_calls walk_steps cavity_triangles \
    flips candidates
  run 0 triangulate "$data/duplicates.node" -o "$work/d.ele" --stats --algorithm green-sibson &&
    grep -q '^duplicates: 2$' "$work/out" || fail "--stats: duplicates is not 2"
}

# canonical <file.ele>: its triangles as vertex triples rotated to start at the smallest
# vertex (orientation kept), sorted: equal for equal triangulations in any listing order.
canonical() {
  awk 'NR > 1 { a = $2; b = $3; c = $4
    if (b < a && b < c) { t = a; a = b; b = c; c = t }
    else if (c < a && c < b) { t = c; c = b; b = a; a = t }
    print a, b, c }' "$1" | sort
}

# --location: the same triangulation whatever the point location; on a random order the grid
# walks far less than the plain walk from the last insertion (O(1) vs O(sqrt n) steps per
# point), and auto picks the grid for the random order.
point_location() {
  local location
  local -a steps=()
  # 3000 points from the Park-Miller generator (products below 2^53: exact in awk's doubles),
  # so the counters are deterministic.
  awk 'BEGIN { n = 3000; s = 12345; print n, 2, 0, 0
    for (i = 1; i <= n; i++) {
      s = (s * 16807) % 2147483647; x = s / 2147483647
      s = (s * 16807) % 2147483647; y = s / 2147483647
      printf "%d %.17g %.17g\n", i, x, y } }' >"$work/random.node"
  for location in auto walk grid; do
    run 0 triangulate "$work/random.node" -o "$work/$location.ele" --algorithm green-sibson \
      --order random --location "$location" --stats || return
    steps[${#steps[@]}]=$(awk '/^walk_steps: / { print $2 }' "$work/out")
    canonical "$work/$location.ele" >"$work/$location.triangles"
    cmp -s "$work/auto.triangles" "$work/$location.triangles" ||
      fail "--location $location: a different triangulation than --location auto"
  done
  run 0 check "$work/random.node" "$work/grid.ele" || fail "check rejected grid.ele"
  # steps = (auto, walk, grid)
  [[ ${steps[0]} -eq ${steps[2]} ]] ||
    fail "--location auto (${steps[0]} walk steps) is not the grid (${steps[2]}) for --order random"
  ((steps[2] * 3 < steps[1])) ||
    fail "--location grid walked ${steps[2]} steps, not under a third of walk's ${steps[1]}"
  run 0 triangulate "$work/random.node" -o "$work/b.ele" --algorithm bowyer-watson \
    --order brio --location grid || return
  run 0 triangulate "$work/random.node" -o "$work/t.ele" --algorithm tanemura-merriam \
    --location walk || return
  canonical "$work/b.ele" | cmp -s "$work/auto.triangles" - ||
    fail "bowyer-watson --location grid: a different triangulation"
  canonical "$work/t.ele" | cmp -s "$work/auto.triangles" - ||
    fail "tanemura-merriam --location walk: a different triangulation"
  expect_error 2 'foo not in' triangulate "$work/random.node" -o "$work/x.ele" --location foo
}

# --threads: bowyer-watson (triangulate, then tetrahedralize) on 1 to 3 threads and on every
# core (0) gives the same triangles or tetrahedra; --stats names the count and the parallel
# counters; a count above 1024 is a usage error.
threads() {
  # 40000 points from the Park-Miller generator (as point_location), enough for parallel rounds.
  awk 'BEGIN { n = 40000; s = 4711; print n, 2, 0, 0
    for (i = 1; i <= n; i++) {
      s = (s * 16807) % 2147483647; x = s / 2147483647
      s = (s * 16807) % 2147483647; y = s / 2147483647
      printf "%d %.17g %.17g\n", i, x, y } }' >"$work/many.node"
  local threads
  for threads in 1 2 3 0; do
    run 0 triangulate "$work/many.node" -o "$work/t$threads.ele" --threads "$threads" --stats || return
    expect_stats 40000 orient2d threads sequential_prefix parallel_rounds parallel_points \
      deferred_points sequential_tail
    canonical "$work/t$threads.ele" >"$work/t$threads.triangles"
    cmp -s "$work/t1.triangles" "$work/t$threads.triangles" ||
      fail "--threads $threads: a different triangulation than --threads 1"
  done
  run 0 triangulate "$work/many.node" -o "$work/x.ele" --threads 2 --stats || return
  grep -q '^threads: 2$' "$work/out" || fail "--threads 2: --stats does not print 'threads: 2'"
  awk '/^parallel_points: / { exit !($2 > 20000) }' "$work/out" ||
    fail "--threads 2: fewer than half of the points inserted in parallel"
  run 0 triangulate "$work/many.node" -o "$work/x.ele" --stats || return
  grep -q '^threads: 1$' "$work/out" || fail "default: --stats does not print 'threads: 1'"
  run 0 check "$work/many.node" "$work/t2.ele" || fail "check rejected the 2-thread output"
  expect_error 2 'threads' triangulate "$work/many.node" -o "$work/x.ele" --threads 5000
  # tetrahedralize --threads: the same for the 3D construction (tetrahedra compared as sorted
  # vertex quadruples, the list sorted).
  awk 'BEGIN { n = 20000; s = 4711; print n, 3, 0, 0
    for (i = 1; i <= n; i++) {
      s = (s * 16807) % 2147483647; x = s / 2147483647
      s = (s * 16807) % 2147483647; y = s / 2147483647
      s = (s * 16807) % 2147483647; z = s / 2147483647
      printf "%d %.17g %.17g %.17g\n", i, x, y, z } }' >"$work/many3.node"
  for threads in 1 2 3 0; do
    run 0 tetrahedralize "$work/many3.node" -o "$work/k$threads.ele" --threads "$threads" --stats || return
    expect_stats 20000 orient3d threads sequential_prefix parallel_rounds parallel_points \
      deferred_points sequential_tail
    awk 'NR > 1 && NF >= 5 { split($2 " " $3 " " $4 " " $5, v, " ")
      for (i = 1; i <= 4; i++) for (j = i + 1; j <= 4; j++) if (v[j] + 0 < v[i] + 0) { t = v[i]; v[i] = v[j]; v[j] = t }
      print v[1], v[2], v[3], v[4] }' "$work/k$threads.ele" | sort >"$work/k$threads.tets"
    cmp -s "$work/k1.tets" "$work/k$threads.tets" ||
      fail "tetrahedralize --threads $threads: different tetrahedra than --threads 1"
  done
  run 0 tetrahedralize "$work/many3.node" -o "$work/x.ele" --threads 2 --stats || return
  grep -q '^threads: 2$' "$work/out" || fail "tetrahedralize --threads 2: no 'threads: 2'"
  awk '/^parallel_points: / { exit !($2 > 10000) }' "$work/out" ||
    fail "tetrahedralize --threads 2: fewer than half of the points inserted in parallel"
  run 0 tetrahedralize "$work/many3.node" -o "$work/x.ele" --stats || return
  grep -q '^threads: 1$' "$work/out" || fail "tetrahedralize default: no 'threads: 1'"
  run 0 check "$work/many3.node" "$work/k2.ele" || fail "check rejected the 2-thread tetrahedra"
  expect_error 2 'threads' tetrahedralize "$work/many3.node" -o "$work/x.ele" --threads 5000
}

# mesh --threads: Delaunay refinement in rounds gives the same mesh (files byte for byte) on
# 1, 2, 3 threads and on every core (0); --threads 2 alone means rounds; --stats prints the
# count, the rounds' counters and phase times; check accepts the mesh; worst-first on two threads is a usage
# error, as a count above 1024; another generator warns that it ignores --threads.
mesh_threads() {
  local threads
  for threads in 1 2 3 0; do
    run 0 mesh --domain square-with-holes --size 0.01 --min-angle 30 --refine-order rounds \
      --threads "$threads" -o "$work/r$threads.ele" --stats || return
    # More threads than cores (3 here, on CI's two) share the cores, silently.
    ! grep -q 'TBB' "$work/err" || fail "mesh --threads $threads: oneTBB wrote $(cat "$work/err")"
    for extension in ele node poly; do
      cmp -s "$work/r1.$extension" "$work/r$threads.$extension" ||
        fail "mesh --threads $threads: a different .$extension than on one thread"
    done
  done
  run 0 mesh --domain square-with-holes --size 0.01 --min-angle 30 --threads 2 \
    -o "$work/two.ele" --stats || return
  cmp -s "$work/r1.ele" "$work/two.ele" || fail "mesh --threads 2: not the rounds' mesh"
  grep -q '^threads: 2$' "$work/out" || fail "mesh --threads 2: no 'threads: 2'"
  awk '/^rounds: / { r = $2 } /^steiner_points: / { s = $2 }
    END { exit !(r > 0 && s > 4 * r) }' "$work/out" ||
    fail "mesh --threads 2: no rounds, or fewer than four points per round"
  # The rounds' phase times: six lines, each a number, summing to at most construct_seconds.
  awk '/^round_(form|probe|accept|fans|queue|steps)_seconds: [0-9.]+$/ { n++; sum += $2 }
    /^construct_seconds: / { c = $2 } END { exit !(n == 6 && sum <= c) }' "$work/out" ||
    fail "mesh --threads 2 --stats: not six round_*_seconds within construct_seconds"
  run 0 check "$work/two.poly" "$work/two.ele" ||
    fail "check rejected the two-thread mesh"
  run 0 mesh --domain square-with-holes --size 0.01 --min-angle 30 -o "$work/w.ele" --stats ||
    return
  grep -q '^threads: 1$' "$work/out" || fail "mesh default: no 'threads: 1'"
  grep -q '^rounds: 0$' "$work/out" || fail "mesh default: not the worst-first refinement"
  ! grep -q '^round_.*_seconds' "$work/out" || fail "mesh default: round phase times printed"
  expect_error 2 'worst-first refinement runs on one thread' mesh --domain square-with-holes \
    --size 0.05 --refine-order worst-first --threads 2 -o "$work/x.ele"
  expect_error 2 'threads' mesh --domain square-with-holes --size 0.05 --threads 5000 \
    -o "$work/x.ele"
  run 0 mesh --domain square-with-holes --size 0.05 --generator frontal --threads 2 \
    -o "$work/f.ele" || return
  grep -q -- '--threads 2 ignored' "$work/out" "$work/err" 2>/dev/null ||
    fail "mesh --generator frontal --threads 2: no warning that --threads is ignored"
}

bad_input() {
  expect_error 2 'nan\.node:[0-9]+: non-finite y coordinate .nan.' \
    triangulate "$data/nan.node" -o "$work/x.ele"
  expect_error 2 'truncated\.node:[0-9]+: file ends after 3 of 5 announced vertices' \
    triangulate "$data/truncated.node" -o "$work/x.ele"
  expect_error 2 'nan\.node:[0-9]+: non-finite' check "$data/nan.node" "$data/kite_delaunay.ele"
  expect_error 2 'kite_bad_vertex\.ele:4: vertex number 9 out of range' \
    check "$data/kite.node" "$data/kite_bad_vertex.ele"
  expect_error 2 'missing\.node: cannot open for reading' triangulate "$work/missing.node" -o "$work/x.ele"
  expect_error 2 'missing\.ele: cannot open for reading' check "$data/kite.node" "$work/missing.ele"
  expect_error 2 'not expected: --bogus' triangulate "$data/kite.node" -o "$work/x.ele" --bogus
  expect_error 2 'foo not in' triangulate "$data/kite.node" -o "$work/x.ele" --algorithm foo
  expect_error 2 'foo not in' triangulate "$data/kite.node" -o "$work/x.ele" --order foo
  expect_error 2 'output is required' triangulate "$data/kite.node"
  expect_error 2 'subcommand is required'
  expect_error 2 'not expected: frobnicate' frobnicate
  expect_error 2 'cannot open for writing' triangulate "$data/kite.node" -o "$work/no/such/dir/x.ele"
  # A directory or a binary file instead of a .node.
  expect_error 2 'is a directory' triangulate "$data" -o "$work/x.ele"
  printf '\x00\x01\x02garbage\n' >"$work/binary.node"
  expect_error 2 'binary\.node:1: a NUL byte at column 1' \
    triangulate "$work/binary.node" -o "$work/x.ele"
  # Help is not an error.
  run 0 --help && grep -q 'triangulate' "$work/out" || fail "--help"
}

check_rejects_non_delaunay() {
  run 1 check "$data/kite.node" "$data/kite_not_delaunay.ele" || return
  [[ $(wc -l <"$work/out") -eq 1 ]] || fail "check: expected one line: $(cat "$work/out")"
  grep -Eq '^not ok: .*kite_not_delaunay\.ele: triangle 1 \(1, 2, 3\): not Delaunay, vertex 4 lies inside its circumcircle$' \
    "$work/out" || fail "check: wrong report: $(cat "$work/out")"
  run 0 check "$data/kite.node" "$data/kite_delaunay.ele" &&
    grep -q '^ok: 2 triangles, exact Delaunay$' "$work/out" || fail "check rejected kite_delaunay.ele"
  # Clockwise triangle: named in the file's numbering too.
  printf '2 3 0\n1 1 2 4\n2 2 4 3\n' >"$work/clockwise.ele"
  run 1 check "$data/kite.node" "$work/clockwise.ele" &&
    grep -q 'triangle 2 (2, 4, 3): not counter-clockwise' "$work/out" ||
    fail "check: clockwise triangle not named: $(cat "$work/out")"
}

cdt() {
  local poly=$data/square_hole_diagonals.poly recovery
  for recovery in swap cavity conforming; do
    run 0 cdt "$poly" -o "$work/$recovery.ele" --recovery "$recovery" --stats || continue
    for ext in ele neigh node poly; do [[ -s "$work/$recovery.$ext" ]] || fail "cdt: $recovery.$ext missing"; done
    grep -Eq '^construct_seconds: [0-9]+\.[0-9]+$' "$work/out" || fail "cdt --stats: no construct_seconds"
    grep -q '^intersections: 1$' "$work/out" || fail "cdt: intersections is not 1: $(cat "$work/out")"
    grep -q 'warning: segments 6 and 5 cross; split at new vertex 9 (2, 2)' "$work/err" ||
      fail "cdt: no crossing warning in the input's numbering: $(cat "$work/err")"
    # The added vertex follows the input's 8 in the .node written beside the .ele.
    head -n 1 "$work/$recovery.node" | grep -q '^9 2 ' || fail "cdt: $recovery.node does not hold 9 vertices"
    run 0 check "$poly" "$work/$recovery.ele" &&
      grep -q '^ok: [0-9]* triangles, exact constrained Delaunay' "$work/out" ||
      fail "check rejected the $recovery output: $(cat "$work/out")"
  done
  run 0 cdt "$poly" -o "$work/cdt.svg" && grep -q '</svg>' "$work/cdt.svg" || fail "cdt: svg"
  # A .node alone is a PSLG without segments.
  run 0 cdt "$data/kite.node" -o "$work/kite.ele" || fail "cdt of a .node"
  # The Delaunay triangulation of a flat rhombus lacks the long diagonal: named in the
  # file's numbering.
  printf '4 2 0 0\n1 0 0\n2 1 -0.2\n3 2 0\n4 1 0.2\n' >"$work/rhombus.node"
  printf '0 2 0 0\n1 0\n1 1 3\n0\n' >"$work/rhombus.poly"
  run 0 triangulate "$work/rhombus.node" -o "$work/rhombus_dt.ele" || return
  run 1 check "$work/rhombus.poly" "$work/rhombus_dt.ele" &&
    grep -q '^not ok: .*segment 1 (1, 3) is missing' "$work/out" || fail "check: missing segment: $(cat "$work/out")"
  # A lone segment encloses nothing: as Triangle does, the exterior is eaten unless --convex-hull.
  run 0 cdt "$work/rhombus.poly" -o "$work/rhombus_cdt.ele" && grep -q '^triangles: 0$' "$work/out" ||
    fail "cdt: rhombus without --convex-hull: $(cat "$work/out")"
  run 0 cdt "$work/rhombus.poly" -o "$work/rhombus_cdt.ele" --convex-hull && grep -q '^triangles: 2$' "$work/out" ||
    fail "cdt: rhombus with --convex-hull: $(cat "$work/out")"
  run 0 check "$work/rhombus.poly" "$work/rhombus_cdt.ele" || fail "check rejected the rhombus CDT: $(cat "$work/out")"
  # Bad input: one line naming file, line and problem.
  printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 4\n0\n' >"$work/dangling.poly"
  expect_error 2 'dangling\.poly:6: segment endpoint 4 names no vertex' cdt "$work/dangling.poly" -o "$work/x.ele"
  printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 nan\n0 0\n0\n' >"$work/nan.poly"
  expect_error 2 'nan\.poly:4: non-finite y coordinate' cdt "$work/nan.poly" -o "$work/x.ele"
  printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 2\n1\n1 inf 0\n' >"$work/inf_hole.poly"
  expect_error 2 'inf_hole\.poly:8: non-finite' cdt "$work/inf_hole.poly" -o "$work/x.ele"
  expect_error 2 'magic not in' cdt "$poly" -o "$work/x.ele" --recovery magic
  # -o IN.ele beside IN.poly would write the result's .poly over the input: refused, input kept.
  printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n' >"$work/keep.poly"
  expect_error 2 'keep\.poly: this output would overwrite the input file' cdt "$work/keep.poly" -o "$work/keep.ele"
  grep -q '^3 0 1$' "$work/keep.poly" || fail "cdt: the input was modified"
  # Zero-length and repeated segments: dropped with a warning each, exit 0.
  printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 1\n2 1 2\n3 2 1\n0\n' >"$work/dropped.poly"
  run 0 cdt "$work/dropped.poly" -o "$work/dropped_cdt.ele" --convex-hull &&
    grep -q 'segment 1 has zero length' "$work/err" && grep -q 'segment 3 repeats segment 2' "$work/err" ||
    fail "cdt: no warnings for dropped segments: $(cat "$work/err")"
}

# A scattered point set with one attribute (the data of the data-dependent criterion), written
# by awk with a fixed seed, and its Delaunay triangulation as the common start.
make_scattered() {
  awk 'BEGIN { srand(7); print "60 2 1 0"; for (i = 1; i <= 60; i++) {
    x = rand(); y = rand(); printf "%d %.17g %.17g %.17g\n", i, x, y, x * x - y } }' >"$work/scattered.node"
  run 0 triangulate "$work/scattered.node" -o "$work/scattered.ele"
}

swap_criteria() {
  # The kite split along its long diagonal: one Delaunay swap fixes it.
  run 0 swap "$data/kite.node" "$data/kite_not_delaunay.ele" -o "$work/kite.ele" --stats || return
  grep -q '^swaps: 1$' "$work/out" || fail "swap kite: expected 1 swap: $(cat "$work/out")"
  grep -Eq '^construct_seconds: [0-9]+\.[0-9]+$' "$work/out" || fail "swap --stats: no construct_seconds"
  for name in edges_tested not_convex constrained swaps; do
    grep -Eq "^$name: [0-9]+$" "$work/out" || fail "swap --stats: no '$name: N' line"
  done
  run 0 check "$data/kite.node" "$work/kite.ele" || fail "swapped kite is not Delaunay"
  make_scattered || return
  local criterion
  for criterion in delaunay max-min-angle min-max-angle min-length data-dependent; do
    run 0 swap "$work/scattered.node" "$work/scattered.ele" -o "$work/$criterion.ele" \
      --criterion "$criterion" --stats || continue
    [[ $(head -n1 "$work/$criterion.ele") == "$(head -n1 "$work/scattered.ele")" ]] ||
      fail "$criterion: triangle count changed"
    if grep -Ev '^[a-z0-9_.]+: ' "$work/out" | grep -q .; then
      fail "swap --stats: a line is not 'name: value'"
    fi
  done
  run 0 swap "$work/scattered.node" "$work/scattered.ele" -o "$work/jnd.ele" \
    --criterion data-dependent --data-cost jnd || fail "data-dependent jnd"
  # Delaunay and max-min angle swapping from the Delaunay start change nothing.
  cmp -s "$work/delaunay.ele" "$work/scattered.ele" || fail "delaunay swapping changed a Delaunay mesh"
  run 0 check "$work/scattered.node" "$work/max-min-angle.ele" || fail "max-min-angle is not Delaunay"
}

min_max() {
  # The local-optimum instance of tests/unit/triangulation/edge_swap_2d_test.cpp: min-max angle
  # swapping from Delaunay stops at 126.87 degrees, edge cutting reaches 113.20.
  printf '6 2 0 0\n0 17 12\n1 17 5\n2 7 16\n3 14 16\n4 10 2\n5 0 8\n' >"$work/local.node"
  run 0 triangulate "$work/local.node" -o "$work/local.ele" || return
  run 0 swap "$work/local.node" "$work/local.ele" -o "$work/swapped.ele" --criterion min-max-angle --stats &&
    grep -q '^max_angle_degrees: 126\.869897' "$work/out" || fail "min-max-angle swapping: $(cat "$work/out")"
  run 0 min-max "$work/local.node" -o "$work/optimal.ele" --stats || return
  grep -q '^max_angle_degrees: 113\.198590' "$work/out" || fail "min-max: $(cat "$work/out")"
  [[ $(head -n1 "$work/optimal.ele") == "$(head -n1 "$work/local.ele")" ]] || fail "min-max: triangle count"
  for name in worst_triangles insertions candidates visited removed_edges; do
    grep -Eq "^$name: [0-9]+$" "$work/out" || fail "min-max --stats: no '$name: N' line"
  done
  grep -Eq '^construct_seconds: [0-9]+\.[0-9]+$' "$work/out" || fail "min-max --stats: no construct_seconds"
  # Collinear points: no triangle, still success; 1-based input gives 1-based output.
  printf '3 2 0 0\n1 0 0\n2 1 1\n3 2 2\n' >"$work/line.node"
  run 0 min-max "$work/line.node" -o "$work/line.ele" && [[ $(head -n1 "$work/line.ele") == "0 3 0" ]] ||
    fail "min-max collinear"
  run 0 min-max "$data/one_based_comments.node" -o "$work/ob.ele" &&
    sed -n 2p "$work/ob.ele" | grep -q '^1 ' || fail "min-max: 1-based numbering"
  run 0 check "$data/one_based_comments.node" "$work/ob.ele" || true  # valid mesh; maybe not Delaunay
  grep -Eq '^(ok|not ok: .*not Delaunay.*)' "$work/out" || fail "min-max output is not a valid mesh: $(cat "$work/out")"
}

swap_bad_input() {
  expect_error 2 'nan\.node:[0-9]+: non-finite y coordinate .nan.' \
    swap "$data/nan.node" "$data/kite_delaunay.ele" -o "$work/x.ele"
  expect_error 2 'nan\.node:[0-9]+: non-finite' min-max "$data/nan.node" -o "$work/x.ele"
  expect_error 2 'kite_bad_vertex\.ele:4: vertex number 9 out of range' \
    swap "$data/kite.node" "$data/kite_bad_vertex.ele" -o "$work/x.ele"
  printf '2 3 0\n1 1 2 4\n2 2 4 3\n' >"$work/clockwise.ele"
  expect_error 2 'clockwise\.ele: triangle 2 \(2, 4, 3\) is not strictly counter-clockwise' \
    swap "$data/kite.node" "$work/clockwise.ele" -o "$work/x.ele"
  printf '2 3 0\n1 1 2 4\n2 1 2 4\n' >"$work/twice.ele"
  expect_error 2 'twice\.ele: edge \(1, 2\) of triangle 2 appears twice' \
    swap "$data/kite.node" "$work/twice.ele" -o "$work/x.ele"
  expect_error 2 'kite\.node: the data-dependent criterion reads the first vertex attribute' \
    swap "$data/kite.node" "$data/kite_delaunay.ele" -o "$work/x.ele" --criterion data-dependent
  expect_error 2 'foo not in' swap "$data/kite.node" "$data/kite_delaunay.ele" -o "$work/x.ele" --criterion foo
  expect_error 2 'the output must be a \.ele file' swap "$data/kite.node" "$data/kite_delaunay.ele" -o "$work/x.vtu"
  expect_error 2 'the output must be a \.ele file' min-max "$data/kite.node" -o "$work/x.svg"
  expect_error 2 'missing\.ele: cannot open for reading' swap "$data/kite.node" "$work/missing.ele" -o "$work/x.ele"
  expect_error 2 'output is required' min-max "$data/kite.node"
}

# Issue 11, hostile inputs: one case per finding (each runs in well under a second).

# A companion that cannot be written (a directory), or a disk that fills (/dev/full behind a
# link), leaves every previous output byte-identical and no temporary file behind.
hostile_data_loss() {
  printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >"$work/square.poly"
  run 0 cdt "$work/square.poly" -o "$work/out.ele" || return
  local before
  before=$(cat "$work/out.ele" "$work/out.neigh" "$work/out.poly" | md5sum)
  rm "$work/out.node" && mkdir "$work/out.node"
  expect_error 2 'out\.node: is a directory' cdt "$work/square.poly" -o "$work/out.ele" --order given
  [[ $(cat "$work/out.ele" "$work/out.neigh" "$work/out.poly" | md5sum) == "$before" ]] ||
    fail "a failing companion changed the previous outputs"
  if [[ -e /dev/full ]]; then
    run 0 triangulate "$data/kite.node" -o "$work/tri.ele" || return
    before=$(md5sum <"$work/tri.ele")
    rm "$work/tri.neigh" && ln -s /dev/full "$work/tri.neigh"
    expect_error 2 'tri\.neigh: write error: No space left on device' \
      triangulate "$data/square_with_center.node" -o "$work/tri.ele"
    [[ $(md5sum <"$work/tri.ele") == "$before" ]] || fail "a full disk changed the previous .ele"
  fi
  ! compgen -G "$work/.*.tmp" >/dev/null || fail "a temporary file was left: $(ls -a "$work")"
}

# Outputs that resolve to an input (the same path, a link, a hard link) are refused at once.
hostile_refuse_inputs() {
  cp "$data/kite.node" "$work/k.node" && cp "$data/kite_delaunay.ele" "$work/k.ele"
  local before
  before=$(md5sum <"$work/k.ele")
  expect_error 2 'k\.ele: this output would overwrite the input file' swap "$work/k.node" "$work/k.ele" -o "$work/./k.ele"
  ln -s k.node "$work/link.ele"
  expect_error 2 'link\.ele: this output would overwrite the input file' triangulate "$work/k.node" -o "$work/link.ele"
  ln "$work/k.ele" "$work/hard.ele"
  expect_error 2 'hard\.ele: this output would overwrite the input file' swap "$work/k.node" "$work/k.ele" -o "$work/hard.ele"
  [[ $(md5sum <"$work/k.ele") == "$before" ]] || fail "an input was changed"
  cmp -s "$work/k.node" "$data/kite.node" || fail "k.node was changed"
}

# /dev/zero and a binary file fail on line 1 at once; a byte order mark is skipped; extensions
# in any case.
hostile_reading() {
  expect_error 2 '/dev/zero:1: a NUL byte at column 1' triangulate /dev/zero -o "$work/x.ele"
  printf '\xef\xbb\xbf4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n' >"$work/bom.NODE"
  run 0 triangulate "$work/bom.NODE" -o "$work/bom.ELE" && grep -q '^triangles: 2$' "$work/out" ||
    fail "a .NODE with a byte order mark: $(cat "$work/out" "$work/err")"
  [[ -s $work/bom.neigh ]] || fail "no .neigh beside bom.ELE"
}

# A hole point on a segment or a vertex: one error naming the file, the line, the hole and the
# segment or vertex, the same for cdt and every generator.
hostile_holes() {
  local square='4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n'
  printf "$square"'1\n1 0.5 0\n' >"$work/on_segment.poly"
  printf "$square"'1\n1 1 1\n' >"$work/on_vertex.poly"
  expect_error 2 'on_segment\.poly:12: hole 1 at \(0\.5, 0\) lies on segment 1' cdt "$work/on_segment.poly" -o "$work/x.ele"
  local generator
  for generator in delaunay-refinement quadtree advancing-front advancing-front-delaunay frontal; do
    expect_error 2 'on_vertex\.poly:12: hole 1 at \(1, 1\) lies on vertex 3' \
      mesh "$work/on_vertex.poly" -o "$work/x.ele" --generator "$generator" --size 0.25
  done
}

# swap and swap3d validate their input as check does: two overlapping triangles that share no
# edge (each counter-clockwise) were swapped into a "result".
hostile_swap_validation() {
  printf '6 2 0 0\n0 0 0\n1 4 0\n2 0 4\n3 1 1\n4 5 1\n5 1 5\n' >"$work/two.node"
  printf '2 3 0\n0 0 1 2\n1 3 4 5\n' >"$work/overlap.ele"
  expect_error 2 'overlap\.ele: not a triangulation of the points of .*two\.node' \
    swap "$work/two.node" "$work/overlap.ele" -o "$work/x.ele"
  [[ ! -e $work/x.ele ]] || fail "swap wrote an output for an invalid input"
}

# Options: integers checked on their text, angles only for the generator that uses them,
# smoothing bounded and stopping early.
hostile_options() {
  expect_error 2 "--seed: '-1' is negative" triangulate "$data/kite.node" -o "$work/x.ele" --seed -1
  expect_error 2 "--seed: '99999999999999999999' is too large" cdt "$data/square_hole_diagonals.poly" -o "$work/x.ele" --seed 99999999999999999999
  expect_error 2 "--max-steiner: '-1' is negative" mesh --domain key -o "$work/x.ele" --max-steiner -1
  expect_error 2 "--smooth: '4000000000' is too large \(at most 1000\)" mesh --domain key -o "$work/x.ele" --smooth 4000000000
  expect_error 2 'apply to --generator delaunay-refinement only; quadtree' mesh --domain key -o "$work/x.ele" --generator quadtree --min-angle 30
  expect_error 2 'must be finite numbers \(got NaN' mesh --domain key -o "$work/x.ele" --min-angle nan
  expect_error 2 'minimum angle 89 is outside' mesh --domain key -o "$work/x.ele" --min-angle 89
  printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >"$work/square.poly"
  run 0 mesh "$work/square.poly" -o "$work/s.ele" --size 0.1 --smooth 1000 --stats || return
  local sweeps
  sweeps=$(awk '/^smoothing_sweeps:/ { print $2 }' "$work/out")
  [[ -n $sweeps && $sweeps -lt 1000 ]] || fail "smoothing did not stop early: $sweeps sweeps"
  printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n1\n1 0.5 0.5 1 0.01\n' >"$work/area.poly"
  # The region's maximum area is applied now (it was read and ignored, with a warning): at
  # least 1 / 0.01 triangles, no warning (more in region_areas).
  run 0 mesh "$work/area.poly" -o "$work/a.ele" && [[ ! -s "$work/err" ]] &&
    awk '/^triangles:/ { exit !($2 >= 100) }' "$work/out" ||
    fail "region maximum area not applied: $(cat "$work/out" "$work/err")"
}

# Messages: raw bytes of a size file are escaped; an unreadable size file is reported as such.
# Region maximum areas (Triangle's -a per region, issue 11): a unit square split at x = 0.5 into
# regions with maximum areas 0.001 and 0.01. Delaunay refinement keeps every triangle of each
# region within its bound (awk's areas, to a relative 1e-12; the exact check is
# tests/regressions/issue_11_region_areas_test.cpp) and the regional attributes; frontal takes
# them as sizes; the generators without regions, and impossible areas, are refused at once.
region_areas() {
  printf '6 2 0 0\n1 0 0\n2 0.5 0\n3 1 0\n4 1 1\n5 0.5 1\n6 0 1\n7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n7 2 5\n0\n2\n1 0.25 0.5 7.5 0.001\n2 0.75 0.5 -3 0.01\n' \
    >"$work/two.poly"
  local generator
  for generator in delaunay-refinement frontal; do
    run 0 mesh "$work/two.poly" --generator "$generator" -o "$work/two_$generator.ele" || continue
    run 0 check "$work/two.poly" "$work/two_$generator.ele" || fail "$generator: check: $(cat "$work/out")"
    # Per attribute: triangle count and largest area.
    awk 'FNR == 1 { file++; next } file == 1 { x[$1] = $2; y[$1] = $3; next }
      /^#/ { next }
      { a = ((x[$3] - x[$2]) * (y[$4] - y[$2]) - (y[$3] - y[$2]) * (x[$4] - x[$2])) / 2
        n[$5]++; if (a > big[$5]) big[$5] = a }
      END { printf "%d %.17g %d %.17g\n", n["7.5"], big["7.5"], n["-3"], big["-3"] }' \
      "$work/two_$generator.node" "$work/two_$generator.ele" >"$work/areas"
    read -r n_fine big_fine n_coarse big_coarse <"$work/areas"
    ((n_fine > 2 * n_coarse && n_coarse >= 50)) || fail "$generator: region counts $n_fine, $n_coarse"
    if [[ $generator == delaunay-refinement ]]; then
      awk -v a="$big_fine" -v b="$big_coarse" 'BEGIN { exit !(a <= 0.001 * (1 + 1e-12) && b <= 0.01 * (1 + 1e-12)) }' ||
        fail "refinement: largest areas $big_fine, $big_coarse above 0.001, 0.01"
    else
      # A size of the equilateral triangle of the area: within frontal's acceptance (1.5 A).
      awk -v a="$big_fine" -v b="$big_coarse" 'BEGIN { exit !(a <= 0.0015 && b <= 0.015) }' ||
        fail "frontal: largest areas $big_fine, $big_coarse"
    fi
  done
  for generator in quadtree advancing-front advancing-front-delaunay; do
    expect_error 2 "two\.poly:18: region maximum area 0\.001: region maximum areas are honoured by delaunay-refinement and frontal only \(--generator $generator\)" \
      mesh "$work/two.poly" --generator "$generator" -o "$work/x.ele"
  done
  # Regional attributes without areas: a generator that carries no regions warns (issue 12).
  sed 's/ 0\.001$/ 0/; s/ 0\.01$/ 0/' "$work/two.poly" >"$work/attributes.poly"
  run 0 mesh "$work/attributes.poly" --generator quadtree -o "$work/x.ele" &&
    grep -q "attributes\.poly:18: 2 regions' attributes ignored: --generator quadtree does not honour regional attributes" "$work/err" ||
    fail "quadtree: no warning about the regional attributes: $(cat "$work/err")"
  run 0 mesh "$work/attributes.poly" --generator frontal -o "$work/x.ele" && [[ ! -s $work/err ]] ||
    fail "frontal warned about regional attributes it carries: $(cat "$work/err")"
  sed 's/7\.5 0\.001$/7.5 1e-12/' "$work/two.poly" >"$work/tiny.poly"
  expect_error 2 "the regions' maximum areas ask for about 5e\+11 or more triangles" mesh "$work/tiny.poly" -o "$work/x.ele"
  run 0 cdt "$work/two.poly" -o "$work/cdt.ele" &&
    grep -q 'two\.poly:18: region maximum areas are not applied (cdt adds no vertices' "$work/err" ||
    fail "cdt: no warning about the areas: $(cat "$work/err")"
}

hostile_messages() {
  printf 'uniform \x1b[31mred\x07\n' >"$work/binary.size"
  expect_error 2 'binary\.size:1: .\\x1b\[31mred\\x07. is not a finite number' mesh --domain key -o "$work/x.ele" --size "$work/binary.size"
  grep -q $'\x1b' "$work/err" && fail "an escape byte reached the terminal"
  mkdir "$work/dir.size"
  expect_error 2 'dir\.size: is a directory' mesh --domain key -o "$work/x.ele" --size "$work/dir.size"
  # A generator's refusal names the input file: a vertex 1e-308 from a corner, joined to it by a
  # segment (refinement cannot follow it in doubles), and a tetrahedron whose facets meet at 45
  # degrees with a Steiner budget too small for it.
  printf '5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 1e-308 1e-308\n5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 1 5\n0\n' >"$work/tiny.poly"
  expect_error 2 'tiny\.poly: segment [0-9]+: its piece .* is too short to split: its split point rounds to one of its ends' mesh "$work/tiny.poly" -o "$work/x.ele"
  printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0.3 0.3 0.3\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n' >"$work/wedge.off"
  expect_error 2 'wedge\.off: delaunay refinement 3d: Steiner point budget of 20 exceeded' tetmesh "$work/wedge.off" --max-volume 0.0001 --max-steiner 20 -o "$work/x.ele"
}

# canonical_tets <file.ele>: each tetrahedron's vertices sorted, the lines sorted: equal for
# equal tetrahedralizations in any listing order.
canonical_tets() {
  awk 'NR > 1 { n = split($2 " " $3 " " $4 " " $5, v, " ")
    for (i = 1; i <= 4; i++) for (j = i + 1; j <= 4; j++) if (v[j] < v[i]) { t = v[i]; v[i] = v[j]; v[j] = t }
    print v[1], v[2], v[3], v[4] }' "$1" | sort
}

# 300 points of a 6 x 6 x 6 integer grid (massively cospherical) and a random cloud, from awk
# with fixed seeds: every algorithm and order gives the same tetrahedra (shared perturbation)
# that `check` accepts, numbered like the 1-based input.
tetrahedralize_all() {
  awk 'BEGIN { print 216, 3, 0, 0; n = 0
    for (x = 0; x < 6; x++) for (y = 0; y < 6; y++) for (z = 0; z < 6; z++) printf "%d %d %d %d\n", ++n, x, y, z }' \
    >"$work/grid.node"
  awk 'BEGIN { srand(11); print 300, 3, 0, 0
    for (i = 1; i <= 300; i++) printf "%d %.17g %.17g %.17g\n", i, rand(), rand(), rand() }' >"$work/cloud.node"
  local node algorithm order base reference
  for node in grid cloud cube_center; do
    local path="$work/$node.node"
    [[ $node == cube_center ]] && path="$data/cube_center.node"
    reference=""
    for algorithm in bowyer-watson green-sibson; do
      for order in given random brio; do
        base="$work/$node.$algorithm.$order"
        run 0 tetrahedralize "$path" -o "$base.ele" --algorithm "$algorithm" --order "$order" --seed 5 || continue
        for ext in ele face neigh; do [[ -s "$base.$ext" ]] || fail "$base.$ext missing"; done
        run 0 check "$path" "$base.ele" && grep -Eq '^ok: [0-9]+ tetrahedra, exact Delaunay$' "$work/out" ||
          fail "check did not accept $base.ele: $(cat "$work/out")"
        canonical_tets "$base.ele" >"$base.tets"
        if [[ -z $reference ]]; then
          reference="$base.tets"
        else
          cmp -s "$reference" "$base.tets" || fail "$node: $algorithm $order differs from $reference"
        fi
      done
    done
  done
  # The cube and its centre: 12 tetrahedra (a cone over the 12 face triangles), 12 hull faces,
  # 1-based like the input (tetrahedron 1 first, vertices 1..9).
  head -n1 "$work/cube_center.bowyer-watson.brio.ele" | grep -q '^12 4 0$' || fail "cube_center: expected 12 tetrahedra"
  head -n1 "$work/cube_center.green-sibson.given.face" | grep -q '^12 0$' || fail "cube_center: expected 12 hull faces"
  sed -n 2p "$work/cube_center.bowyer-watson.brio.ele" | grep -q '^1 ' || fail "cube_center: first tetrahedron is not 1"
  if awk 'NR > 1 { for (i = 2; i <= 5; i++) if ($i < 1 || $i > 9) bad = 1 } END { exit !bad }' \
    "$work/cube_center.green-sibson.random.ele"; then
    fail "cube_center: vertex numbers outside 1..9"
  fi
  [[ $(tail -n +2 "$work/cube_center.bowyer-watson.given.neigh" | grep -o -- '-1' | wc -l) -eq 12 ]] ||
    fail "cube_center.neigh: expected 12 hull sides"
  # Every unit cube of the grid is cut into tetrahedra: 6 x volume sums to 6 x 125.
  awk 'NR == FNR { if (FNR > 1) { x[$1] = $2; y[$1] = $3; z[$1] = $4 }; next }
    FNR > 1 { a = $2; b = $3; c = $4; d = $5
      ux = x[b] - x[a]; uy = y[b] - y[a]; uz = z[b] - z[a]
      vx = x[c] - x[a]; vy = y[c] - y[a]; vz = z[c] - z[a]
      wx = x[d] - x[a]; wy = y[d] - y[a]; wz = z[d] - z[a]
      det = ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)
      if (det <= 0) bad++
      sum += det }
    END { if (bad > 0 || sum != 750) { print "volume", sum, "non-positive", bad; exit 1 } }' \
    "$work/grid.node" "$work/grid.green-sibson.brio.ele" >"$work/volume" ||
    fail "grid: TetGen-oriented volumes: $(cat "$work/volume")"
}

tetrahedralize_formats() {
  run 0 tetrahedralize "$data/cube_center.node" -o "$work/cube.msh" || return
  expect_msh "$work/cube.msh" '^3 1 4 12$' "no block of 12 tetrahedra (type 4) in a volume"
  run 0 tetrahedralize "$data/cube_center.node" -o "$work/cube.vtu" --algorithm green-sibson
  expect_vtu "$work/cube.vtu" 'NumberOfPoints="9" NumberOfCells="12"'
  expect_error 2 'svg pictures are 2D only' tetrahedralize "$data/cube_center.node" -o "$work/cube.svg"
  [[ ! -e "$work/cube.svg" ]] || fail "cube.svg written despite the error"
  expect_error 2 "unsupported output extension '\.off'" tetrahedralize "$data/cube_center.node" -o "$work/x.off"
  # -o beside the input would overwrite it with the .face or .neigh of the result: refused.
  cp "$data/cube_center.node" "$work/keep.node"
  printf '1 0\n' >"$work/keep.face"
  expect_error 2 'keep\.face: this output would overwrite the input file' tetrahedralize "$work/keep.face" -o "$work/keep.ele"
}

tetrahedralize_stats() {
  run 0 tetrahedralize "$data/cube_center.node" -o "$work/s.ele" --stats --algorithm green-sibson || return
  expect_stats 9 orient3d points duplicates orient_calls insphere_calls walk_steps cavity_tets \
    outside_hull splits_1_4 splits_2_6 splits_edge flips_2_3 flips_3_2 flips_4_4 unflippable
  # Duplicates are merged into their first copy and counted.
  printf '6 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 1 0 0\n5 -0 0 0\n' >"$work/dup.node"
  run 0 tetrahedralize "$work/dup.node" -o "$work/dup.ele" --stats && grep -q '^duplicates: 2$' "$work/out" ||
    fail "--stats: duplicates is not 2: $(cat "$work/out")"
  if awk 'NR > 1 { for (i = 2; i <= 5; i++) if ($i > 3) bad = 1 } END { exit !bad }' "$work/dup.ele"; then
    fail "dup.ele uses a repeated point instead of its first copy"
  fi
}

tetrahedralize_bad_input() {
  printf '3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 nan 0\n' >"$work/nan.node"
  expect_error 2 'nan\.node:4: non-finite y coordinate .nan.' tetrahedralize "$work/nan.node" -o "$work/x.ele"
  expect_error 2 'kite\.node:[0-9]+: dimension must be 3, got 2' tetrahedralize "$data/kite.node" -o "$work/x.ele"
  printf '4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n' >"$work/short.node"
  expect_error 2 'short\.node:4: file ends after 3 of 4 announced vertices' tetrahedralize "$work/short.node" -o "$work/x.ele"
  printf '5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n5 2 3 0\n' >"$work/flat.node"
  expect_error 2 'flat\.node: all 5 points lie in one plane' tetrahedralize "$work/flat.node" -o "$work/x.ele"
  [[ ! -e "$work/x.ele" ]] || fail "x.ele written for bad input"
  expect_error 2 'foo not in' tetrahedralize "$data/cube_center.node" -o "$work/x.ele" --algorithm foo
  expect_error 2 'tanemura-merriam not in' tetrahedralize "$data/cube_center.node" -o "$work/x.ele" --algorithm tanemura-merriam
  expect_error 2 'output is required' tetrahedralize "$data/cube_center.node"
  # check: a TetGen .ele naming a vertex the .node lacks; a 2D .ele against a 3D .node.
  printf '1 4 0\n1 1 2 3 10\n' >"$work/bad_vertex.ele"
  expect_error 2 'bad_vertex\.ele:2: node number 10 out of range' check "$data/cube_center.node" "$work/bad_vertex.ele"
  expect_error 2 'nodes per tetrahedron must be 4' check "$data/cube_center.node" "$data/kite_delaunay.ele"
}

check_rejects_non_delaunay_3d() {
  # Five points: a triangle and two apexes whose segment pierces it. The Delaunay
  # tetrahedralization has 2 tetrahedra; the 3 around the apexes' edge are valid, not Delaunay.
  printf '5 3 0 0\n1 0 0 0\n2 4 0 0\n3 0 4 0\n4 1 1 10\n5 1 1 -10\n' >"$work/five.node"
  run 0 tetrahedralize "$work/five.node" -o "$work/five.ele" || return
  head -n1 "$work/five.ele" | grep -q '^2 4 0$' || fail "five: expected 2 tetrahedra"
  # TetGen orientation (positive volume): (4, 5, a, b) for the edges ab of triangle 1-2-3.
  printf '3 4 0\n1 4 5 2 1\n2 4 5 3 2\n3 4 5 1 3\n' >"$work/flipped.ele"
  run 1 check "$work/five.node" "$work/flipped.ele" || return
  grep -Eq '^not ok: .*flipped\.ele: tetrahedron [1-3] \(.*\): not Delaunay, vertex [0-9] lies inside its circumsphere$' \
    "$work/out" || fail "check: wrong report: $(cat "$work/out")"
  # The corners as the file lists them (1-based, in its order), not in the internal order.
  grep -Eq 'tetrahedron 1 \(4, 5, 2, 1\)|tetrahedron 2 \(4, 5, 3, 2\)|tetrahedron 3 \(4, 5, 1, 3\)' "$work/out" ||
    fail "check: corners not in the file's order: $(cat "$work/out")"
  # The same tetrahedra inside out are named as such.
  printf '3 4 0\n1 5 4 2 1\n2 4 5 3 2\n3 4 5 1 3\n' >"$work/inverted.ele"
  run 1 check "$work/five.node" "$work/inverted.ele" &&
    grep -q 'tetrahedron 1 (5, 4, 2, 1): not positively oriented' "$work/out" || fail "check: inverted: $(cat "$work/out")"
  # A missing tetrahedron leaves the boundary open.
  printf '1 4 0\n1 1 2 3 4\n' >"$work/one.ele"
  run 1 check "$work/five.node" "$work/one.ele" && grep -q 'point 5 is not a vertex' "$work/out" ||
    fail "check: one tetrahedron: $(cat "$work/out")"
}

swap3d_criteria() {
  # Two tetrahedra on a face whose far apex is inside the near sphere: one 2-3 swap, Delaunay.
  run 0 swap3d "$data/pair.node" "$data/pair.ele" -o "$work/pair.ele" --stats || return
  grep -q '^flips_23: 1$' "$work/out" || fail "swap3d pair: expected one 2-3 swap: $(cat "$work/out")"
  grep -q '^stalled_faces: 0$' "$work/out" || fail "swap3d pair: stalled: $(cat "$work/out")"
  grep -q '^tetrahedra: 3$' "$work/out" || fail "swap3d pair: expected 3 tetrahedra"
  [[ $(head -n1 "$work/pair.ele") == "3 4 0" ]] || fail "swap3d pair: .ele header $(head -n1 "$work/pair.ele")"
  grep -Eq '^construct_seconds: [0-9]+\.[0-9]+$' "$work/out" || fail "swap3d --stats: no construct_seconds"
  for name in faces_examined edges_examined flips_23 flips_32 flips_44 flips_22 not_flippable; do
    grep -Eq "^$name: [0-9]+$" "$work/out" || fail "swap3d --stats: no '$name: N' line"
  done
  # The output reads back (TetGen orientation round trip) and swapping it again changes nothing.
  run 0 swap3d "$data/pair.node" "$work/pair.ele" -o "$work/again.ele" --stats || return
  grep -q '^flips_23: 0$' "$work/out" || fail "swap3d: second pass swapped: $(cat "$work/out")"
  cmp -s "$work/pair.ele" "$work/again.ele" || fail "swap3d: second pass changed the mesh"
  # The stall instance of tests/unit/triangulation/edge_face_swap_3d_test.cpp: 1-based files,
  # Delaunay swapping stops with 6 faces not locally Delaunay and no valid swap.
  run 0 swap3d "$data/stall7.node" "$data/stall7_placing.ele" -o "$work/stall.ele" --stats --quality || return
  grep -q '^stalled_faces: 6$' "$work/out" || fail "swap3d stall: $(cat "$work/out")"
  sed -n 2p "$work/stall.ele" | grep -q '^1 ' || fail "swap3d: 1-based input must give 1-based output"
  for name in min_dihedral_degrees max_dihedral_degrees min_volume_edge mean_volume_edge max_radius_edge slivers; do
    grep -Eq "^$name: [0-9.e+-]+$" "$work/out" || fail "swap3d --quality: no '$name: value' line"
  done
  [[ $(grep -c '^dihedral_degrees\[' "$work/out") -eq 18 ]] || fail "swap3d --quality: expected 18 histogram bins"
  [[ $(grep -c '^radius_edge\[' "$work/out") -eq 21 ]] || fail "swap3d --quality: expected 21 radius-edge bins"
  grep -Eq '^radius_edge_over_2: [0-9]+$' "$work/out" || fail "swap3d --quality: no radius_edge_over_2 line"
  for criterion in max-min-dihedral min-max-dihedral volume-edge; do
    run 0 swap3d "$data/stall7.node" "$data/stall7_placing.ele" -o "$work/$criterion.ele" --criterion "$criterion" \
      --stats --quality || continue
    grep -q "^criterion: $criterion$" "$work/out" || fail "swap3d: criterion line for $criterion"
    ! grep -q '^stalled_faces' "$work/out" || fail "swap3d: stalled_faces is a Delaunay counter"
    if grep -Ev '^[a-z_0-9]+(\[[0-9.]+,([0-9.]+|inf)[])])?: [^ ]+$' "$work/out" | grep -q .; then
      fail "swap3d --stats --quality: a line is not 'name: value'"
    fi
    # With edge removal: counted; under max-min-dihedral never a smaller smallest angle (every
    # removal after the face swaps' fixpoint raises the sorted smallest angles).
    local without
    without=$(sed -n 's/^min_dihedral_degrees: //p' "$work/out")
    run 0 swap3d "$data/stall7.node" "$data/stall7_placing.ele" -o "$work/$criterion-er.ele" \
      --criterion "$criterion" --edge-removal --stats --quality || continue
    grep -Eq '^edge_removal_removals: [0-9]+$' "$work/out" || fail "swap3d --edge-removal: no edge_removal_removals line"
    if [[ $criterion == max-min-dihedral ]]; then
      local with
      with=$(sed -n 's/^min_dihedral_degrees: //p' "$work/out")
      awk -v a="$with" -v b="$without" 'BEGIN { exit !(a + 0 >= b + 0) }' ||
        fail "swap3d --edge-removal: smallest angle $with below $without without it"
    fi
  done
  expect_error 2 'edge-removal needs a quality criterion' \
    swap3d "$data/stall7.node" "$data/stall7_placing.ele" -o "$work/x.ele" --edge-removal
}

swap3d_bad_input() {
  expect_error 2 'nan3d\.node:[0-9]+: non-finite z coordinate' \
    swap3d "$data/nan3d.node" "$data/pair.ele" -o "$work/x.ele"
  expect_error 2 'planar\.node:1: dimension must be 3' swap3d "$data/planar.node" "$data/pair.ele" -o "$work/x.ele"
  expect_error 2 'pair_bad_node\.ele:3: node number 9 out of range' \
    swap3d "$data/pair.node" "$data/pair_bad_node.ele" -o "$work/x.ele"
  # Corners in the file's order (the reader swaps the last two internally; the file says 1 0 2 3).
  expect_error 2 'pair_inverted\.ele: tetrahedron 0 \(1, 0, 2, 3\) is negatively oriented' \
    swap3d "$data/pair.node" "$data/pair_inverted.ele" -o "$work/x.ele"
  expect_error 2 'pair_overlap\.ele: face .* is shared by 3 tetrahedra' \
    swap3d "$data/pair.node" "$data/pair_overlap.ele" -o "$work/x.ele"
  expect_error 2 'foo not in' swap3d "$data/pair.node" "$data/pair.ele" -o "$work/x.ele" --criterion foo
  expect_error 2 'the output must be a \.ele file' swap3d "$data/pair.node" "$data/pair.ele" -o "$work/x.node"
  expect_error 2 'missing\.ele: cannot open for reading' swap3d "$data/pair.node" "$work/missing.ele" -o "$work/x.ele"
}

# `exactmesh mesh`: each built-in domain in each format, a .poly with an angle and size bound
# (checked as constrained Delaunay by `check`, min angle from --quality), a size file, and the
# error lines: unknown generators, bounds, files, open and broken domains.
mesh() {
  local domain ext
  for domain in square-with-holes naca0012 key three-element; do
    run 0 mesh --domain "$domain" -o "$work/$domain.ele" --quality --stats || continue
    for ext in ele neigh node poly; do [[ -s "$work/$domain.$ext" ]] || fail "mesh: $domain.$ext missing"; done
    grep -Eq '^triangles: [1-9][0-9]{3,}$' "$work/out" || fail "mesh $domain: too few triangles: $(cat "$work/out")"
    grep -Eq '^quality.min_angle: [0-9]+\.[0-9]+$' "$work/out" || fail "mesh $domain: no quality.min_angle"
    grep -Eq '^quality.size_conformity: min [0-9.]+ median [0-9.]+ max (0\.[0-9]+|1\.0000[0-9]*) ' "$work/out" ||
      fail "mesh $domain: size conformity above 1: $(grep size_conformity "$work/out")"
    grep -Eq '^construct_seconds: [0-9]+\.[0-9]+$' "$work/out" || fail "mesh $domain --stats: no construct_seconds"
    grep -Eq '^steiner_points: [1-9][0-9]*$' "$work/out" || fail "mesh $domain --stats: no steiner_points"
  done
  # No small input angle in square-with-holes: every angle at least the bound.
  run 0 mesh --domain square-with-holes -o "$work/swh.vtu" --min-angle 30 --quality &&
    awk '/^quality.min_angle:/ { exit !($2 >= 30) }' "$work/out" || fail "mesh: min angle below 30: $(cat "$work/out")"
  # The polish (on by default: min(20.7 + 10, 32)) lifts square-with-holes to 30.7; off, it adds nothing.
  run 0 mesh --domain square-with-holes -o "$work/polish.ele" --quality --stats &&
    awk '/^quality.min_angle:/ { a = $2 } /^polish_points:/ { p = $2 } END { exit !(a >= 30.7 && p > 0) }' "$work/out" ||
    fail "mesh: the polish did not reach 30.7: $(cat "$work/out")"
  run 0 mesh --domain square-with-holes -o "$work/nopolish.ele" --polish-angle 0 --stats &&
    grep -q '^polish_points: 0$' "$work/out" || fail "mesh --polish-angle 0: $(cat "$work/out")"
  for ext in msh vtu svg; do
    run 0 mesh --domain key -o "$work/key.$ext" && [[ -s "$work/key.$ext" ]] || fail "mesh: key.$ext"
  done
  grep -q '</svg>' "$work/key.svg" || fail "mesh: svg not closed"
  # A .poly (1-based, a hole, crossing diagonals): valid constrained Delaunay, angles >= 28.
  run 0 mesh "$data/square_hole_diagonals.poly" -o "$work/square.ele" --min-angle 28 --size 0.3 --quality || return
  awk '/^quality.min_angle:/ { exit !($2 >= 28) }' "$work/out" || fail "mesh: min angle below 28: $(cat "$work/out")"
  grep -q 'warning: segments 6 and 5 cross' "$work/err" || fail "mesh: no crossing warning: $(cat "$work/err")"
  run 0 check "$data/square_hole_diagonals.poly" "$work/square.ele" &&
    grep -q '^ok: [0-9]* triangles, exact constrained Delaunay' "$work/out" ||
    fail "check rejected the mesh: $(cat "$work/out")"
  # check --conforming: the same mesh is a valid mesh of the domain; one triangle turned
  # clockwise is not (exit 1, naming it); --conforming without a .poly is an input error.
  run 0 check --conforming "$data/square_hole_diagonals.poly" "$work/square.ele" &&
    grep -q '^ok: [0-9]* triangles, exact valid mesh' "$work/out" || fail "check --conforming: $(cat "$work/out")"
  awk 'NR == 2 { t = $2; $2 = $3; $3 = t } { print }' "$work/square.ele" >"$work/folded.ele"
  cp "$work/square.node" "$work/folded.node" && cp "$work/square.poly" "$work/folded.poly"
  run 1 check --conforming "$data/square_hole_diagonals.poly" "$work/folded.ele" &&
    grep -q '^not ok: .*folded\.ele: ' "$work/out" || fail "check --conforming accepted a clockwise triangle: $(cat "$work/out")"
  expect_error 2 '--conforming needs an IN\.poly' check --conforming "$data/kite.node" "$data/kite_delaunay.ele"
  # A size file: a point source at the centre, capped.
  printf '# size\nuniform 0.5\npoint 2 2 0.05 0.5 1.5\n' >"$work/size.txt"
  run 0 mesh "$data/square_hole_diagonals.poly" -o "$work/graded.ele" --size "$work/size.txt" --quality &&
    grep -Eq '^quality.size_conformity: .* max (0\.[0-9]+|1\.0000[0-9]*) ' "$work/out" ||
    fail "mesh: graded size not met: $(cat "$work/out")"
  # Smoothing: reported apart, the result still exact constrained Delaunay, mean quality up.
  run 0 mesh "$data/square_hole_diagonals.poly" -o "$work/smooth.ele" --size 0.3 --smooth 3 --quality --stats || return
  grep -Eq '^smooth_seconds: [0-9]+\.[0-9]+$' "$work/out" || fail "mesh --smooth: no smooth_seconds: $(cat "$work/out")"
  awk '/^quality.mean_min_angle:/ { after = $2 } /^smoothing.mean_min_angle_before:/ { before = $2 }
       END { exit !(after > before) }' "$work/out" || fail "mesh --smooth: mean quality not better: $(cat "$work/out")"
  run 0 check "$data/square_hole_diagonals.poly" "$work/smooth.ele" &&
    grep -q '^ok: [0-9]* triangles, exact constrained Delaunay' "$work/out" ||
    fail "check rejected the smoothed mesh: $(cat "$work/out")"
  # Every generator of the registry: a .poly with crossing diagonals and a hole at a given size,
  # checked exactly (constrained Delaunay, or a valid mesh for the conforming generators), and
  # the key domain with its counters and construct_seconds; without --size a generator that
  # needs one takes the input's spacing.
  local generator kind
  # Free vertices of a .node beside its .poly (the .poly announces 0 vertices; 5-7 are on no
  # segment): every generator keeps them (issue 11), and check verifies that every input vertex
  # in the domain is a mesh vertex.
  printf '7 2 0 0\n1 0 0\n2 3 0\n3 3 2\n4 0 2\n5 1 1\n6 2 0.5\n7 2.9 1.9\n' >"$work/free.node"
  printf '0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >"$work/free.poly"
  for generator in delaunay-refinement:delaunay quadtree:conforming advancing-front:conforming \
    advancing-front-delaunay:conforming frontal:delaunay; do
    kind=${generator#*:}
    generator=${generator%%:*}
    run 0 mesh "$work/free.poly" -o "$work/free-$generator.ele" --generator "$generator" --size 0.3 &&
      run 0 check $([[ $kind == delaunay ]] || echo --conforming) "$work/free.poly" "$work/free-$generator.ele" &&
      grep -q '^ok: ' "$work/out" || fail "mesh --generator $generator, free vertices: $(cat "$work/out")"
    run 0 mesh "$data/square_hole_diagonals.poly" -o "$work/$generator.ele" --generator "$generator" --size 0.3 \
      --quality || continue
    awk '/^quality.triangles:/ { exit !($2 > 100) }' "$work/out" || fail "mesh --generator $generator: $(cat "$work/out")"
    if [[ $kind == delaunay ]]; then
      run 0 check "$data/square_hole_diagonals.poly" "$work/$generator.ele" &&
        grep -q '^ok: .* exact constrained Delaunay' "$work/out" || fail "check $generator: $(cat "$work/out")"
    else
      run 0 check --conforming "$data/square_hole_diagonals.poly" "$work/$generator.ele" &&
        grep -q '^ok: .* exact valid mesh' "$work/out" || fail "check --conforming $generator: $(cat "$work/out")"
    fi
    run 0 mesh --domain key -o "$work/key-$generator.vtu" --generator "$generator" --stats &&
      grep -Eq '^construct_seconds: [0-9]+\.[0-9]+$' "$work/out" || fail "mesh --domain key --generator $generator --stats"
    run 0 mesh "$data/square_hole_diagonals.poly" -o "$work/$generator-own.ele" --generator "$generator" ||
      fail "mesh --generator $generator without --size"
  done
  # Errors: one line each.
  expect_error 2 "unknown generator 'magic'" mesh --domain key -o "$work/x.ele" --generator magic
  expect_error 2 "unknown domain 'moon'" mesh --domain moon -o "$work/x.ele"
  expect_error 2 'minimum angle 40 is outside \[0, 34\]' mesh --domain key -o "$work/x.ele" --min-angle 40
  expect_error 2 'polish angle 40' mesh --domain key -o "$work/x.ele" --polish-angle 40
  expect_error 2 'either an input \.poly file or --domain' mesh "$data/square_hole_diagonals.poly" --domain key -o "$work/x.ele"
  expect_error 2 'either an input \.poly file or --domain' mesh -o "$work/x.ele"
  printf 'point 1 2 3\n' >"$work/bad_size.txt"
  expect_error 2 'bad_size\.txt:1: point takes 5 numbers' mesh --domain key -o "$work/x.ele" --size "$work/bad_size.txt"
  expect_error 2 "--size 'nowhere' is neither a number > 0, a readable size file, nor an expression in x and y: " \
    mesh --domain key -o "$work/x.ele" --size nowhere
  expect_error 2 "--size '0.1 \\+\\* x' is neither .*: " mesh --domain key -o "$work/x.ele" --size '0.1 +* x'
  expect_error 2 'size' mesh --domain key -o "$work/x.ele" --size '-1'
  # A size expression in x and y: graded towards x = 4, every edge within it.
  run 0 mesh "$data/square_hole_diagonals.poly" -o "$work/expr.ele" --size '0.02 + 0.1 * abs(4 - x)' --quality &&
    grep -Eq '^quality.size_conformity: .* max (0\.[0-9]+|1\.0000[0-9]*) ' "$work/out" &&
    awk '/^quality.triangles:/ { exit !($2 > 1000) }' "$work/out" ||
    fail "mesh --size EXPR: $(cat "$work/out") $(cat "$work/err")"
  printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2 0\n1 1 2\n2 2 3\n0\n' >"$work/open.poly"
  expect_error 2 'the segments enclose no region' mesh "$work/open.poly" -o "$work/x.ele"
  printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 nan\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n' >"$work/nan.poly"
  expect_error 2 'nan\.poly:4: non-finite y coordinate' mesh "$work/nan.poly" -o "$work/x.ele"
  expect_error 2 'more than 50 Steiner points|more than the --max-steiner budget' mesh --domain key -o "$work/x.ele" --max-steiner 50
  # A self-intersecting boundary (a bow tie): split where it crosses, a warning, a valid mesh.
  printf '4 2 0 0\n1 0 0\n2 2 2\n3 2 0\n4 0 2\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >"$work/bowtie.poly"
  run 0 mesh "$work/bowtie.poly" -o "$work/bowtie.1.ele" &&
    grep -q 'cross; split at new vertex 5 (1, 1)' "$work/err" || fail "mesh: bow tie: $(cat "$work/err")"
  run 0 check "$work/bowtie.poly" "$work/bowtie.1.ele" || fail "check rejected the bow tie mesh: $(cat "$work/out")"
  printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n' >"$work/keep.poly"
  expect_error 2 'keep\.poly: this output would overwrite the input file' mesh "$work/keep.poly" -o "$work/keep.ele"
}

# Impossible sizes (issue 11): refused at once with exit 2, naming the size and the estimate,
# never "out of memory" (exit 3) nor --min-angle; a size that is 0 in the domain names the point.
mesh_impossible_sizes() {
  printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >"$work/unit.poly"
  printf 'uniform 1e-300\n' >"$work/tiny.size"
  local generator
  for generator in delaunay-refinement quadtree advancing-front advancing-front-delaunay frontal; do
    expect_error 2 'the size \(uniform 1e-300\) asks for far more than 1e300 triangles.*--max-steiner' \
      mesh "$work/unit.poly" --generator "$generator" --size 1e-300 -o "$work/a.ele"
    expect_error 2 'asks for about 1.1547e\+14 or more triangles' \
      mesh "$work/unit.poly" --generator "$generator" --size 1e-7 -o "$work/b.ele"
    expect_error 2 'the size function \(expression x\) is 0 at \(0, 0\)' \
      mesh "$work/unit.poly" --generator "$generator" --size x -o "$work/c.ele"
    expect_error 2 'the size \(uniform 1e-300\) asks for' \
      mesh "$work/unit.poly" --generator "$generator" --size "$work/tiny.size" -o "$work/d.ele"
  done
  # A built-in domain's curves are discretized by --size: refused before that (at 1e-9 that
  # made "out of memory", exit 3, under a 4 GB limit; at 1e-7 minutes before the error).
  expect_error 2 'the size \(uniform 1e-09\) asks for about .* or more triangles' \
    mesh --domain naca0012 --size 1e-9 -o "$work/e.ele"
}

# exactmesh adapt (issue 13): every 2D method on a sample domain and on a .poly, the error falls
# over the cycles, the field is the .node's attribute, the exact check passes (exit 0), a budget
# holds; a 2D Triangle mesh as input (its vertex numbering kept, `check --conforming` passes, a
# field file); 3D insertion and h-refinement on the cube and on a TetGen mesh read back, a field
# file; the field as node data / point data "u" in .msh and .vtu (read back by meshio when it is
# installed).
adapt() {
  local method
  for method in insertion h-refinement steiner remesh local-remesh; do
    run 0 adapt --domain naca0012 --method "$method" --field 'tanh(20*(x+0.5*y-0.6))' --cycles 2 \
      --max-vertices 30000 -o "$work/$method.ele" --stats || continue
    awk '/^cycle 0:/ { e0 = $8 } /^cycle 2:/ { e2 = $8 } END { exit !(e0 > 0 && e2 > 0 && e2 < e0) }' \
      "$work/out" || fail "adapt $method: the max error did not fall: $(cat "$work/out")"
    grep -Eq '^construct_seconds: [0-9]+\.[0-9]+$' "$work/out" || fail "adapt $method: no construct_seconds"
    awk '/^vertices:/ { exit !($2 <= 30000) }' "$work/out" || fail "adapt $method: budget: $(grep vertices: "$work/out")"
    head -1 "$work/$method.node" | grep -Eq '^[0-9]+ 2 1 0' || fail "adapt $method: the .node carries no field"
  done
  run 0 adapt "$data/square_hole_diagonals.poly" --field 'x*x + y' --cycles 2 -o "$work/poly.vtu" &&
    grep -q '<DataArray type="Float64" Name="u"' "$work/poly.vtu" || fail "adapt .poly -> .vtu: no field"
  # A 2D Triangle mesh as input: the domain with three holes, meshed, then adapted from its files.
  run 0 mesh --domain square-with-holes -o "$work/swh.ele" || return
  local vertices
  vertices=$(head -1 "$work/swh.node" | awk '{ print $1 }')
  for method in insertion h-refinement; do
    run 0 adapt "$work/swh.node" "$work/swh.ele" --method "$method" --field 'tanh(20*(y-0.5))' \
      --cycles 2 -o "$work/given-$method.ele" || continue
    awk '/^cycle 2:/ { exit !($3 > '"$vertices"') }' "$work/out" || fail "adapt 2D mesh $method: no refinement: $(cat "$work/out")"
    run 0 check "$work/swh.poly" "$work/given-$method.ele" --conforming ||
      fail "adapt 2D mesh $method: check --conforming: $(cat "$work/out")"
    # The input's vertices first, at their numbers and places.
    cmp -s <(awk 'NR > 1 && NR <= '"$vertices"' + 1 { print $1, $2, $3 }' "$work/swh.node") \
      <(awk 'NR > 1 && NR <= '"$vertices"' + 1 { print $1, $2, $3 }' "$work/given-$method.node") ||
      fail "adapt 2D mesh $method: the input's vertices are not kept first"
  done
  # A mesh that is not Delaunay (the quadtree's): insertion starts from its CDT and says so.
  run 0 mesh --domain key --generator quadtree -o "$work/quad.ele" &&
    run 0 adapt "$work/quad.node" "$work/quad.ele" --field 'x*y' --cycles 1 -o "$work/quad-adapted.ele" &&
    grep -q 'not the constrained Delaunay triangulation' "$work/err" &&
    run 0 check "$work/quad.poly" "$work/quad-adapted.ele" --conforming || fail "adapt quadtree mesh"
  # A 1-based mesh keeps its numbering.
  printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n' >"$work/unit.node"
  printf '2 3 0\n1 1 2 3\n2 1 3 4\n' >"$work/unit.ele"
  run 0 adapt "$work/unit.node" "$work/unit.ele" --field 'tanh(10*(x-0.3))' --cycles 2 -o "$work/unit-out.ele" &&
    sed -n 2p "$work/unit-out.ele" | grep -q '^1 ' && sed -n 2p "$work/unit-out.node" | grep -q '^1 0 0 ' ||
    fail "adapt 1-based mesh: numbering not kept"
  # A 2D field file (the adapted mesh with its own field), written to .msh and .vtu with it.
  local count
  count=$(head -1 "$work/given-insertion.node" | awk '{ print $1 }')
  for ext in msh vtu; do
    run 0 adapt "$work/given-insertion.node" "$work/given-insertion.ele" --cycles 0 \
      --field-file "$work/given-insertion.node" -o "$work/field.$ext" || fail "adapt 2D --field-file -> .$ext"
  done
  awk '/^\$NodeData/ { d = 1; n = 0; next } /^\$EndNodeData/ { d = 0 } d { n++ } END { exit !(n == 8 + '"$count"') }' \
    "$work/field.msh" && grep -q '^"u"$' "$work/field.msh" || fail "adapt .msh: no node data u of $count nodes"
  # The field in the .msh is the field file's, value for value.
  cmp -s <(awk 'NR > 1 { print $1 + 1, $4 }' "$work/given-insertion.node") \
    <(awk '/^\$NodeData/ { d = 1; skip = 8; next } /^\$EndNodeData/ { d = 0 } d && skip-- <= 0 { print $1, $2 }' "$work/field.msh") ||
    fail "adapt .msh: the node data is not the field file's"
  grep -q '<PointData Scalars="u">' "$work/field.vtu" || fail "adapt .vtu: no point data u"
  run 0 adapt --domain cube --field 'x+y' --cycles 1 -o "$work/cube-field.msh" &&
    grep -q '^\$NodeData$' "$work/cube-field.msh" || fail "adapt 3D .msh: no node data"
  run 0 adapt --domain cube --field 'x+y' --cycles 1 -o "$work/cube-field.vtu" &&
    grep -q 'Name="u"' "$work/cube-field.vtu" || fail "adapt 3D .vtu: no point data"
  # meshio (installed by scripts/bootstrap) reads the field back: one value per point.
  for file in field.msh field.vtu cube-field.msh cube-field.vtu; do
    /usr/bin/python3 -c 'import sys, meshio
m = meshio.read(sys.argv[1])
u = m.point_data["u"]
assert len(u) == len(m.points), (len(u), len(m.points))' "$work/$file" || fail "meshio cannot read the field of $file"
  done
  run 0 adapt --domain key --field 'tanh(30*(x-0.5-0.2*t))' --steps 3 --dt 1 --cycles 2 --derefine \
    --threshold 0.5 -o "$work/steps.svg" &&
    [[ $(grep -c '^step [1-9]' "$work/out") -eq 3 ]] || fail "adapt --steps: $(cat "$work/out")"
  grep -q '</svg>' "$work/steps.svg" || fail "adapt: svg not closed"
  run 0 adapt --domain square-with-holes --field 'tanh(20*(y-0.5))' --cycles 2 --smooth 2 --move 2 \
    -o "$work/moved.ele" --stats && grep -Eq '^movement_moves: [1-9]' "$work/out" ||
    fail "adapt --move: $(cat "$work/out")"
  # 3D.
  for method in insertion h-refinement; do
    run 0 adapt --domain cube --method "$method" --field 'tanh(10*(x+y+z-1.5))' --cycles 2 \
      -o "$work/cube-$method.ele" --stats || continue
    for ext in ele face neigh node; do
      [[ -s "$work/cube-$method.$ext" ]] || fail "adapt 3D: cube-$method.$ext missing"
    done
  done
  # Read back: the insertion result as input, its own field as the field file.
  run 0 adapt "$work/cube-insertion.node" "$work/cube-insertion.ele" --field-file "$work/cube-insertion.node" \
    --cycles 1 -o "$work/again.ele" || fail "adapt 3D from files"
  run 0 adapt --domain cube --method h-refinement --field 'tanh(10*(x-0.3*t))' --steps 2 --dt 1 --derefine \
    -o "$work/steps3.vtu" || fail "adapt 3D --steps"
}

adapt_bad_input() {
  expect_error 2 'give either --field EXPR or --field-file FILE' adapt --domain key -o "$work/a.ele"
  expect_error 2 'not an expression in x, y, z and t' adapt --domain key --field 'x +' -o "$work/a.ele"
  expect_error 2 "field 'log\(x\)' is NaN at" adapt --domain key --field 'log(x)' -o "$work/a.ele"
  expect_error 2 "unknown adaptation method 'magic'" adapt --domain key --field x --method magic -o "$work/a.ele"
  expect_error 2 "unknown indicator 'curvature'" adapt --domain key --field x --indicator curvature -o "$work/a.ele"
  expect_error 2 '--method steiner is 2D only' adapt --domain cube --method steiner --field x -o "$work/a.ele"
  expect_error 2 '--threshold must be a finite number' adapt --domain key --field x --threshold -1 -o "$work/a.ele"
  expect_error 2 '--steps needs an analytic --field' adapt --domain cube --field-file "$data/cube_center.node" \
    --steps 2 -o "$work/a.ele"
  expect_error 2 'would break the nesting' adapt --domain key --field x --method h-refinement --smooth 1 -o "$work/a.ele"
  expect_error 2 '--derefine goes with' adapt --domain key --field x --method steiner --steps 1 --derefine -o "$work/a.ele"
  expect_error 2 "unknown domain 'moon'" adapt --domain moon --field x -o "$work/a.ele"
  # A field file whose points are not the mesh's.
  run 0 adapt --domain cube --field x --cycles 0 -o "$work/c.ele" || return
  expect_error 2 "a field file must be a .node with the mesh's points" \
    adapt "$work/c.node" "$work/c.ele" --field-file "$data/cube_center.node" -o "$work/d.ele"
  # A 2D mesh: a field file of another point count, a vertex the .node lacks, an inverted triangle.
  printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n' >"$work/sq.node"
  printf '2 3 0\n1 1 2 3\n2 1 3 4\n' >"$work/sq.ele"
  printf '3 2 1 0\n1 0 0 5\n2 1 0 5\n3 1 1 5\n' >"$work/three.node"
  printf '4 2 1 0\n1 0 0 5\n2 1 0 5\n# moved\n3 1 1.5 5\n4 0 1 5\n' >"$work/moved.node"
  printf '2 3 0\n1 1 2 3\n2 1 3 5\n' >"$work/missing.ele"
  printf '2 3 0\n1 1 2 3\n2 1 4 3\n' >"$work/inverted.ele"
  expect_error 2 'three.node: 3 points, the mesh has 4' \
    adapt "$work/sq.node" "$work/sq.ele" --field-file "$work/three.node" -o "$work/a.ele"
  expect_error 2 'moved.node:5: point \(1, 1.5\) is not the mesh' \
    adapt "$work/sq.node" "$work/sq.ele" --field-file "$work/moved.node" -o "$work/a.ele"
  expect_error 2 'missing.ele:3: vertex number 5 out of range' \
    adapt "$work/sq.node" "$work/missing.ele" --field x -o "$work/a.ele"
  expect_error 2 'inverted.ele: triangle 2 \(1, 4, 3\) is not strictly counter-clockwise' \
    adapt "$work/sq.node" "$work/inverted.ele" --field x -o "$work/a.ele"
  expect_error 2 '--field-file: a run from a .poly or --domain makes its own mesh' \
    adapt --domain key --field-file "$work/three.node" -o "$work/a.ele"
  # No output file is left behind by a refused run.
  [[ ! -e "$work/a.ele" ]] || fail "adapt: a refused run wrote its output"
}

# Advancing layers (issue 14): --layers and --quads; the mixed mesh in .vtu and .msh read back by
# meshio (quads and triangles as printed), the counters of --stats, the quality note; every bad
# value or combination refused with exit status 2 and one line.
# expect_meshio_cells <file in $work> <quads> <triangles>: meshio reads that many of each.
expect_meshio_cells() {
  /usr/bin/python3 -c 'import sys, meshio
m = meshio.read(sys.argv[1])
count = {c.type: len(c.data) for c in m.cells}
assert count.get("quad", 0) == int(sys.argv[2]), count
assert count.get("triangle", 0) == int(sys.argv[3]), count' "$work/$1" "$2" "$3" ||
    fail "meshio does not read $2 quads and $3 triangles from $1"
}

layers() {
  run 0 mesh --domain naca0012 --generator advancing-layers --layers 1e-5,1.2 --quads \
    -o "$work/naca.vtu" --stats --quality || return
  local quads triangles
  quads=$(awk '/^quads: / { print $2; exit }' "$work/out")
  triangles=$(awk '/^triangles: / { print $2; exit }' "$work/out")
  [[ $quads -gt 1000 ]] || fail "layers: $quads quads: $(cat "$work/out")"
  for counter in stacks layers stopped_aspect_ratio stopped_size stopped_collision \
    stopped_neighbour stopped_max_layers layer_quads fill_triangles max_wall_aspect_ratio \
    construct_seconds quality.note quality.quad_max_angle quality.quad_max_aspect_ratio; do
    grep -Eq "^$counter: " "$work/out" || fail "layers --stats/--quality: no $counter line"
  done
  (($(awk '/^max_wall_aspect_ratio: / { print $2 }' "$work/out") >= 1000)) ||
    fail "layers: the aspect ratio at the wall is below 1000: $(cat "$work/out")"
  run 0 mesh --domain naca0012 --generator advancing-layers --layers 1e-5,1.2 --quads \
    -o "$work/naca.msh" || return
  for file in naca.vtu naca.msh; do
    expect_meshio_cells "$file" "$quads" "$triangles"
  done
  run 0 mesh --domain naca0012 --generator advancing-layers --layers 1e-4,1.2,20 -o "$work/naca.ele" &&
    ! grep -q '^quads:' "$work/out" || fail "layers: split quads still reported as quads"
  # A .poly: its hole loop is the wall (no markers); the graded default size for the fill; a
  # square without a hole has no wall (a warning, the fill alone).
  printf '8 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 0.4 0.4\n6 0.6 0.4\n7 0.6 0.6\n8 0.4 0.6\n8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 6 7\n7 7 8\n8 8 5\n1\n1 0.5 0.5\n' >"$work/holed.poly"
  run 0 mesh "$work/holed.poly" --generator advancing-layers --layers 1e-3,1.2 --quads \
    -o "$work/holed.msh" --stats &&
    grep -Eq '^fan_corners: 4$' "$work/out" && grep -Eq '^quads: [1-9]' "$work/out" &&
    grep -Eq '^2 1 3 [1-9][0-9]*$' "$work/holed.msh" || fail "layers on a .poly: $(cat "$work/out")"
  printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' >"$work/square.poly"
  run 0 mesh "$work/square.poly" --generator advancing-layers --layers 1e-3,1.2 -o "$work/square.1.ele" &&
    grep -q 'no wall' "$work/err" || fail "layers without a wall: no warning: $(cat "$work/err")"
  expect_error 2 'a \.ele file holds triangles only' \
    mesh --domain naca0012 --generator advancing-layers --layers 1e-4,1.2 --quads -o "$work/x.ele"
  expect_error 2 'first height must be a finite number > 0 \(got 0\)' \
    mesh --domain naca0012 --generator advancing-layers --layers 0,1.2 -o "$work/x.vtu"
  expect_error 2 'growth ratio must be in \[1, 10\] \(got 0\.5\)' \
    mesh --domain naca0012 --generator advancing-layers --layers 1e-4,0.5 -o "$work/x.vtu"
  expect_error 2 'number of layers must be a whole number' \
    mesh --domain naca0012 --generator advancing-layers --layers 1e-4,1.2,0 -o "$work/x.vtu"
  expect_error 2 'expected FIRST_HEIGHT,GROWTH\[,MAX_LAYERS\]' \
    mesh --domain naca0012 --generator advancing-layers --layers 1e-4 -o "$work/x.vtu"
  expect_error 2 'needs --layers' mesh --domain naca0012 --generator advancing-layers -o "$work/x.vtu"
  expect_error 2 'apply to --generator advancing-layers .*only, not frontal' \
    mesh --domain naca0012 --generator frontal --layers 1e-4,1.2 -o "$work/x.vtu"
  expect_error 2 '--smooth would move the layers' \
    mesh --domain naca0012 --generator advancing-layers --layers 1e-4,1.2 --smooth 2 -o "$work/x.vtu"
}

# same_metric_report METRIC1 METRIC2: the key's mesh at size 0.1 gets the same metric report
# lines (quality.metric_*) against both metric fields.
same_metric_report() {
  local first
  run 0 mesh --domain key -o "$work/m_out.ele" --size 0.1 --quality --metric "$1" || return
  first=$(grep '^quality.metric_' "$work/out")
  run 0 mesh --domain key -o "$work/m_out.ele" --size 0.1 --quality --metric "$2" || return
  [[ -n "$first" && "$first" == "$(grep '^quality.metric_' "$work/out")" ]] ||
    fail "--metric $1 and --metric $2 give different reports: $first / $(grep '^quality.metric_' "$work/out")"
}

# `mesh --generator advancing-layers --o-mesh`: the truncated O-mesh variant on the three-element
# airfoil (three rings, cells removed in the gaps), its counters, a mixed .msh that meshio reads;
# split into triangles on the NACA 0012; refused for the other generators.
omesh() {
  run 0 mesh --domain three-element --generator advancing-layers --layers 1e-4,1.2 --o-mesh \
    --quads -o "$work/three.msh" --stats --quality || return
  local quads triangles cells
  quads=$(awk '/^quads: / { print $2; exit }' "$work/out")
  triangles=$(awk '/^triangles: / { print $2; exit }' "$work/out")
  cells=$(awk '/^omesh_cells: / { print $2 }' "$work/out")
  [[ $quads -gt 1000 && $quads -eq $cells ]] || fail "o-mesh: $quads quads, $cells cells: $(cat "$work/out")"
  for counter in omesh_min_ring_layers omesh_max_ring_layers omesh_removed_fold omesh_removed_step \
    quality.quad_max_angle; do
    grep -Eq "^$counter: " "$work/out" || fail "o-mesh --stats/--quality: no $counter line"
  done
  grep -Eq '^omesh_rings: 3$' "$work/out" || fail "o-mesh: not three rings: $(cat "$work/out")"
  grep -Eq '^omesh_removed_overlap: [1-9][0-9]*$' "$work/out" ||
    fail "o-mesh: no cell removed in the gaps: $(cat "$work/out")"
  expect_meshio_cells three.msh "$quads" "$triangles"
  run 0 mesh --domain naca0012 --generator advancing-layers --layers 1e-4,1.2 --o-mesh \
    -o "$work/naca.ele" --stats || return
  ! grep -Eq '^quads: [1-9]' "$work/out" || fail "o-mesh: split cells still reported as quads"
  cells=$(awk '/^omesh_cells: / { print $2 }' "$work/out")
  grep -Eq "^layer_triangles: $((2 * cells))$" "$work/out" ||
    fail "o-mesh: $cells cells not split in two triangles each: $(cat "$work/out")"
  expect_error 2 '--o-mesh applies to --generator advancing-layers only, not frontal' \
    mesh --domain naca0012 --generator frontal --o-mesh -o "$work/x.vtu"
  expect_error 2 '--o-mesh applies to --generator advancing-layers only, not stretched-delaunay' \
    mesh --domain naca0012 --generator stretched-delaunay --layers 1e-4,1.2 --o-mesh -o "$work/x.vtu"
}

# `mesh --metric`: the stretched-mesh quality report against an expression or a metric file
# (.node with 3 attributes M11 M12 M22 or 4, a stretching vector, and its .ele), for any
# generator; bad metrics are exit 2
# with one message naming the file, line and value (or the point), and leave no output.
mesh_metric() {
  # Isotropic size 0.1 written as a metric, on a mesh of size 0.1: most edges near unit length.
  run 0 mesh --domain key -o "$work/k.ele" --size 0.1 --quality --metric '100;0;100' || return
  grep -Eq '^quality.metric: expression 100;0;100$' "$work/out" || fail "no metric line: $(cat "$work/out")"
  grep -Eq '^quality.metric_edge_length: min 0\.[0-9]+ median 0\.[5-9][0-9]* max [01]\.[0-9]+ \([0-9]+ edges, [0-9.]+% in \[1/sqrt2, sqrt2\]\)$' "$work/out" ||
    fail "metric edge lengths: $(grep metric_edge "$work/out")"
  grep -Eq '^quality.metric_shape: min 0\.[0-9]+ median 0\.[6-9][0-9]* mean ' "$work/out" ||
    fail "metric shape: $(grep metric_shape "$work/out")"
  grep -Eq '^quality.above_150_degrees: 0 of [0-9]+ triangles$' "$work/out" || fail "angles: $(cat "$work/out")"
  grep -Eq '^quality.aspect_ratio: min 1\.[0-9]+ ' "$work/out" || fail "aspect: $(cat "$work/out")"
  # Any generator, a stretched metric (0.01 in x, 1 in y): isotropic edges are far too long in x.
  run 0 mesh --domain key -o "$work/f.ele" --generator frontal --size 0.1 --quality --metric '1e4;0;1' || return
  grep -Eq '^quality.metric_edge_length: .* max ([2-9]|[1-9][0-9]+)\.[0-9]+ ' "$work/out" ||
    fail "stretched metric: $(grep metric_edge "$work/out")"
  # A metric file, 1-based, with a comment; its field covers the domain.
  printf '# metric\n4 2 3 0\n1 -1 -1 100 0 100\n2 3 -1 100 0 100\n3 3 1 100 0 100\n4 -1 1 100 50 100\n' >"$work/m.node"
  printf '2 3 0\n1 1 2 3\n2 1 3 4\n' >"$work/m.ele"
  run 0 mesh --domain key -o "$work/m_out.ele" --size 0.1 --quality --metric "$work/m.node" || return
  grep -Eq '^quality.metric: background mesh: 4 vertices, 2 triangles$' "$work/out" ||
    fail "metric file: $(cat "$work/out")"
  # The same isotropic size 0.1 as matrices and as stretching vectors (direction, size 0.1 along,
  # aspect ratio 1): the same report.
  printf '4 2 3 0\n1 -1 -1 100 0 100\n2 3 -1 100 0 100\n3 3 1 100 0 100\n4 -1 1 100 0 100\n' >"$work/iso.node"
  printf '4 2 4 0\n1 -1 -1 1 0 0.1 1\n2 3 -1 0 2 0.1 1\n3 3 1 1 1 0.1 1\n4 -1 1 -3 0 0.1 1\n' >"$work/vec.node"
  cp "$work/m.ele" "$work/iso.ele"
  cp "$work/m.ele" "$work/vec.ele"
  same_metric_report "$work/iso.node" "$work/vec.node" || return
  # A stretching vector along x, 0.01 along and aspect ratio 100: 'M11;M12;M22' = '1e4;0;1e8'.
  printf '4 2 4 0\n1 -1 -1 1 0 0.01 100\n2 3 -1 1 0 0.01 100\n3 3 1 1 0 0.01 100\n4 -1 1 1 0 0.01 100\n' >"$work/str.node"
  cp "$work/m.ele" "$work/str.ele"
  same_metric_report "$work/str.node" '1e4;0;1e8' || return
  printf '4 2 4 0\n1 -1 -1 1 0 0.1 1\n2 3 -1 0 0 0.1 1\n3 3 1 1 1 0.1 1\n4 -1 1 -3 0 0.1 1\n' >"$work/zero.node"
  cp "$work/m.ele" "$work/zero.ele"
  expect_error 2 'zero\.node:3: vertex 2: .*direction' \
    mesh --domain key -o "$work/x.ele" --size 0.1 --quality --metric "$work/zero.node"
  # Without --quality: a warning, not silence.
  run 0 mesh --domain key -o "$work/w.ele" --size 0.1 --metric '1;0;1' || return
  grep -q 'ignored without --quality' "$work/err" || fail "no warning: $(cat "$work/err")"
  # Bad metrics: one message each, exit 2, no output left behind.
  printf '# metric\n4 2 3 0\n1 -1 -1 100 0 100\n2 3 -1 100 0 100\n3 3 1 100 0 100\n4 -1 1 1 2 1\n' >"$work/bad.node"
  cp "$work/m.ele" "$work/bad.ele"
  expect_error 2 'bad\.node:6: vertex 4: metric \(M11, M12, M22\) = \(1, 2, 1\) is not positive definite' \
    mesh --domain key -o "$work/x.ele" --size 0.1 --quality --metric "$work/bad.node"
  printf '2 3 0\n1 1 3 2\n2 1 3 4\n' >"$work/cw.ele"
  cp "$work/m.node" "$work/cw.node"
  expect_error 2 'cw\.ele: background mesh: triangle 0: inverted' \
    mesh --domain key -o "$work/x.ele" --size 0.1 --quality --metric "$work/cw.node"
  printf '1 2 2 0\n1 0 0 1 1\n' >"$work/two.node"
  expect_error 2 'two\.node: a metric file.s vertices carry 3 attributes M11 M12 M22 or 4 DIR_X DIR_Y SIZE_ALONG ASPECT_RATIO; this one has 2' \
    mesh --domain key -o "$work/x.ele" --size 0.1 --quality --metric "$work/two.node"
  cp "$work/m.node" "$work/lonely.node"
  expect_error 2 'lonely\.node: the metric file.s triangles belong in .*lonely\.ele, which does not exist' \
    mesh --domain key -o "$work/x.ele" --size 0.1 --quality --metric "$work/lonely.node"
  expect_error 2 "--metric '1;2' is neither a readable metric file .* \(2 parts\)" \
    mesh --domain key -o "$work/x.ele" --size 0.1 --quality --metric '1;2'
  expect_error 2 "M12 'z': Unexpected token" \
    mesh --domain key -o "$work/x.ele" --size 0.1 --quality --metric '1;z;1'
  expect_error 2 "--metric '1;x;1' at \(.*\): metric \(M11, M12, M22\) = \(1, .*, 1\) is not positive definite" \
    mesh --domain key -o "$work/x.ele" --size 0.1 --quality --metric '1;x;1'
  [[ ! -e "$work/x.ele" ]] || fail "mesh --metric: a refused run wrote its output"
}

mesh_metric_delaunay() {
  # A boundary layer along y = 0 on the NACA 0012 domain: stretched cells, most edges of unit
  # metric length, the generator's counters and construct_seconds.
  run 0 mesh --domain naca0012 --generator metric-delaunay -o "$work/md.vtu" --stats --quality \
    --metric '400;0;1/(0.0005+0.3*abs(y))^2' || return
  grep -Eq '^quality.metric_edge_length: .* edges, (9[0-9]|100)\.[0-9]+% in \[1/sqrt2, sqrt2\]\)$' "$work/out" ||
    fail "unit edges: $(grep metric_edge "$work/out")"
  grep -Eq '^quality.aspect_ratio: min [0-9.]+ median [0-9.]+ max ([1-9][0-9]{2,})\.' "$work/out" ||
    fail "no stretched cells: $(grep aspect_ratio "$work/out")"
  for counter in boundary_points passes proposals too_close inserted rejected cavity_corrections swaps swap_budget_hits; do
    grep -Eq "^$counter: [0-9]+$" "$work/out" || fail "no $counter: $(cat "$work/out")"
  done
  grep -Eq '^construct_seconds: [0-9.]+$' "$work/out" || fail "no construct_seconds"
  [[ -s "$work/md.vtu" ]] || fail "no .vtu written"
  # Without --metric it meshes to the size's isotropic metric; with neither, the default size.
  run 0 mesh --domain key --generator metric-delaunay -o "$work/k.ele" --size 0.1 --quality || return
  grep -Eq '^quality.min_angle: ' "$work/out" || fail "no quality report: $(cat "$work/out")"
  # A metric asking for far too many triangles is refused at once, naming its estimate.
  expect_error 2 "the metric \(expression 1e16;0;1e16\) asks for about .* triangles" \
    mesh --domain key --generator metric-delaunay -o "$work/x.ele" --metric '1e16;0;1e16'
  [[ ! -e "$work/x.ele" ]] || fail "a refused run wrote its output"
  # stretched-delaunay: O-meshes about the airfoil, its counters.
  run 0 mesh --domain naca0012 --generator stretched-delaunay --layers 1e-4,1.2 -o "$work/sd.vtu" \
    --stats --quality --metric '1;0;1' || return
  for counter in components omesh_points outside_domain overlap_dropped points swaps reswaps smoothing_moves flat_swaps; do
    grep -Eq "^$counter: [0-9]+$" "$work/out" || fail "no $counter: $(cat "$work/out")"
  done
  # Without --metric, --quality measures it against its own per-vertex metrics.
  run 0 mesh --domain naca0012 --generator stretched-delaunay --layers 1e-4,1.2 -o "$work/sd.ele" \
    --quality --staggered-layers || return
  grep -Fq "quality.metric: the generator's own per-vertex metrics" "$work/out" || fail "no own-metric report: $(cat "$work/out")"
  # Staggered layers and the far field's own metric: most edges unit (measured 95.8%; 75.8% before).
  grep -Eq '^quality.metric_edge_length: .*, (9[0-9])\.[0-9]+% in \[1/sqrt2, sqrt2\]\)$' "$work/out" || fail "unit-edge share: $(cat "$work/out")"
  expect_error 2 "needs --layers" mesh --domain naca0012 --generator stretched-delaunay -o "$work/x.ele"
  expect_error 2 "--staggered-layers applies to --generator stretched-delaunay only" \
    mesh --domain naca0012 --generator frontal --staggered-layers -o "$work/x.ele"
  # A wake behind the trailing edge: its counters; refused elsewhere and when negative.
  run 0 mesh --domain naca0012 --generator stretched-delaunay --layers 1e-4,1.2 --wake 2 \
    -o "$work/sdw.ele" --stats || return
  grep -Eq '^trailing_edges: 1$' "$work/out" || fail "no trailing edge: $(cat "$work/out")"
  grep -Eq '^wake_points: [1-9][0-9]*$' "$work/out" || fail "no wake points: $(cat "$work/out")"
  for counter in wake_dropped wake_omesh_dropped; do
    grep -Eq "^$counter: [0-9]+$" "$work/out" || fail "no $counter: $(cat "$work/out")"
  done
  expect_error 2 "--wake applies to --generator stretched-delaunay only, not frontal" \
    mesh --domain naca0012 --generator frontal --wake 2 -o "$work/x.ele"
  expect_error 2 "--wake -1: a length in chords" \
    mesh --domain naca0012 --generator stretched-delaunay --layers 1e-4,1.2 --wake -1 -o "$work/x.ele"
  # The metric smoothed and graded on a first mesh (a jump in size from 0.01 to 0.2 at x = 0.5,
  # given as a stretching vector), its counters; bad values and combinations refused.
  run 0 mesh --domain square-with-holes --generator metric-delaunay -o "$work/mg.ele" --stats \
    --quality --metric '1;0;x<0.5?0.01:0.2;1' --metric-smoothing 2,0.3 --metric-gradation 0.3 || return
  for counter in background_vertices background_triangles smoothing_passes gradation_passes gradation_corrections; do
    grep -Eq "^metric_$counter: [1-9][0-9]*$" "$work/out" || fail "no metric_$counter: $(cat "$work/out")"
  done
  grep -Eq '^metric_gradation_converged: 1$' "$work/out" || fail "gradation did not converge: $(cat "$work/out")"
  grep -Eq '^quality.metric: background mesh: ' "$work/out" || fail "not measured in the graded metric: $(cat "$work/out")"
  expect_error 2 "--metric-smoothing '0,2': PASSES" mesh --domain key --generator metric-delaunay \
    -o "$work/x.ele" --metric '1;0;0.1;1' --metric-smoothing 0,2
  expect_error 2 "--metric-smoothing '3,2': WEIGHT must be a number in \[0, 1\]" mesh --domain key \
    --generator metric-delaunay -o "$work/x.ele" --metric '1;0;0.1;1' --metric-smoothing 3,2
  expect_error 2 "metric gradation -1: must be finite and >= 0" mesh --domain key \
    --generator metric-delaunay -o "$work/x.ele" --metric '1;0;0.1;1' --metric-gradation -1
  expect_error 2 "need --metric" mesh --domain key --generator metric-delaunay -o "$work/x.ele" \
    --metric-gradation 0.2
  expect_error 2 "--generator frontal does not use --metric" mesh --domain key --generator frontal \
    -o "$work/x.ele" --metric '1;0;0.1;1' --metric-gradation 0.2
  expect_error 2 "ASPECT_RATIO" mesh --domain key --generator metric-delaunay -o "$work/x.ele" \
    --metric '1;0;0.1;1;2'
  expect_error 2 "--quads applies to --generator advancing-layers only, not stretched-delaunay" \
    mesh --domain naca0012 --generator stretched-delaunay --layers 1e-4,1.2 --quads -o "$work/x.vtu"
}

# The advancing-front min-max generator (issue 14): --layers optional. With --layers 1e-5,1.2 on
# the NACA 0012 the wall aspect ratio reaches 1000 with no angle above 150 degrees (measured
# 1448 and 119.6); its counters; without layers an isotropic mesh (--smooth allowed then); bad
# values and combinations refused with exit status 2.
mesh_min_max_front() {
  run 0 mesh --domain naca0012 --generator min-max-front --layers 1e-5,1.2 -o "$work/mm.ele" \
    --stats --quality || return
  for counter in boundary_points wall_loops stacks layers layer_points stopped_aspect_ratio \
    stopped_collision stopped_too_close stopped_neighbour stopped_max_layers passes front_edges \
    front_points rejected_outside rejected_too_close edge_insertions delaunay_flips min_max_swaps \
    triangles max_wall_aspect_ratio; do
    grep -Eq "^$counter: [0-9]+$" "$work/out" || fail "no $counter: $(cat "$work/out")"
  done
  (($(awk '/^max_wall_aspect_ratio: / { print $2 }' "$work/out") >= 1000)) ||
    fail "min-max-front: the aspect ratio at the wall is below 1000: $(cat "$work/out")"
  awk '/^quality.max_angle: / { found = 1; bad = !($2 < 150) } END { exit !found || bad }' \
    "$work/out" || fail "min-max-front: an angle above 150 degrees: $(grep max_angle "$work/out")"
  run 0 mesh --domain naca0012 --generator min-max-front -o "$work/iso.ele" --stats --quality \
    --smooth 1 || return
  grep -Eq '^layer_points: 0$' "$work/out" && grep -Eq '^front_points: [1-9][0-9]*$' "$work/out" ||
    fail "min-max-front without layers: $(cat "$work/out")"
  awk '/^quality.min_angle: / { found = 1; bad = !($2 > 10) } END { exit !found || bad }' \
    "$work/out" || fail "min-max-front without layers: $(grep min_angle "$work/out")"
  expect_error 2 '--quads applies to --generator advancing-layers only, not min-max-front' \
    mesh --domain naca0012 --generator min-max-front --layers 1e-4,1.2 --quads -o "$work/x.vtu"
  expect_error 2 'growth ratio must be in \[1, 10\] \(got 0\.5\)' \
    mesh --domain naca0012 --generator min-max-front --layers 1e-4,0.5 -o "$work/x.ele"
  expect_error 2 '--smooth would move the layers' \
    mesh --domain naca0012 --generator min-max-front --layers 1e-4,1.2 --smooth 2 -o "$work/x.ele"
  expect_error 2 'point budget' \
    mesh --domain naca0012 --generator min-max-front --max-steiner 10 -o "$work/x.ele"
}

# --view and --shade on every command that writes .svg (issue 18): the viewBox is the window,
# fewer triangles drawn than the whole mesh, a clipPath, the colour bar; invalid windows and
# pictures options on a non-.svg output are usage errors that write nothing.
svg_view() {
  run 0 triangulate "$data/square_with_center.node" -o "$work/tri.svg" --view 0,0,0.5,1 \
    --shade min-angle || return
  grep -q 'viewBox="0 0 500.00 ' "$work/tri.svg" || fail "triangulate --view: viewBox: $(head -c 400 "$work/tri.svg")"
  grep -q '<clipPath id="view">' "$work/tri.svg" || fail "triangulate --view: no clipPath"
  grep -q 'smallest angle of each triangle' "$work/tri.svg" || fail "triangulate --shade: no colour bar"
  run 0 cdt "$data/square_hole_diagonals.poly" -o "$work/cdt.svg" --view 0,0,1,1 &&
    grep -q '<clipPath id="view">' "$work/cdt.svg" || fail "cdt --view"
  run 0 mesh --domain key --size 0.05 -o "$work/key.svg" --shade min-angle || return
  run 0 mesh --domain key --size 0.05 -o "$work/tooth.svg" --shade min-angle --view 1.2,-0.5,1.6,-0.1 || return
  grep -q 'viewBox="0 0 1000.00 1' "$work/tooth.svg" || fail "mesh --view: viewBox: $(head -c 400 "$work/tooth.svg")"
  local whole zoom
  whole=$(grep -o 'Z' "$work/key.svg" | wc -l)
  zoom=$(grep -o 'Z' "$work/tooth.svg" | wc -l)
  ((zoom > 0 && 5 * zoom < whole)) || fail "mesh --view: $zoom triangles drawn of $whole"
  grep -Eq '<desc>[0-9]+ points, [0-9]+ triangles, [1-9][0-9]* in the window' "$work/tooth.svg" ||
    fail "mesh --view: desc: $(grep '<desc>' "$work/tooth.svg")"
  run 0 adapt --domain square-with-holes --field 'tanh(20*(y-0.5))' --cycles 1 -o "$work/adapt.svg" \
    --view 0.25,0.25,0.75,0.75 --shade min-angle &&
    grep -q '<clipPath id="view">' "$work/adapt.svg" || fail "adapt --view"
  local view
  for view in '1,2,3' '0,0,0,1' '1,0,0,1' '0,1,1,0' 'nan,0,1,1' '0,0,inf,1' 'a,b,c,d' '0,0,1,1e999' '0,0,1,1,'; do
    expect_error 2 '^exactmesh: error: --view: ' mesh --domain key -o "$work/bad.svg" --view "$view"
    expect_error 2 '^exactmesh: error: --view: ' triangulate "$data/kite.node" -o "$work/bad.svg" --view "$view"
  done
  expect_error 2 'X1 \(0\) must be greater than X0 \(1\)' cdt "$data/square_hole_diagonals.poly" \
    -o "$work/bad.svg" --view 1,0,0,1
  expect_error 2 'not finite' adapt --domain key --field x --cycles 1 -o "$work/bad.svg" --view 0,0,1,nan
  expect_error 2 'draw \.svg pictures; the output is not a \.svg' mesh --domain key -o "$work/bad.ele" --view 0,0,1,1
  expect_error 2 'draw \.svg pictures' triangulate "$data/kite.node" -o "$work/bad.msh" --shade min-angle
  expect_error 2 'draw \.svg pictures' adapt --domain cube --field x --cycles 1 -o "$work/bad.vtu" --view 0,0,1,1
  expect_error 2 'shade' mesh --domain key -o "$work/bad.svg" --shade max-angle
  expect_error 2 'view' tetrahedralize "$data/cube_center.node" -o "$work/bad.ele" --view 0,0,1,1
  ! compgen -G "$work/bad.*" >/dev/null || fail "a file was written despite an error: $(ls "$work"/bad.*)"
}

# A unit cube as a 1-based TetGen .poly with facet markers 1..6 (quadrilateral facets).
write_cube_poly() {
  cat >"$1" <<'POLY'
# cube
8 3 0 0
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
5 0 0 1
6 1 0 1
7 1 1 1
8 0 1 1
6 1
1 0 1
4 1 2 3 4
1 0 2
4 5 6 7 8
1 0 3
4 1 2 6 5
1 0 4
4 2 3 7 6
1 0 5
4 3 4 8 7
1 0 6
4 4 1 5 8
0
POLY
}

tetmesh() {
  write_cube_poly "$work/cube.poly"
  run 0 tetmesh "$work/cube.poly" -o "$work/cube.ele" || return
  local f
  for f in ele node face neigh; do [[ -s "$work/cube.$f" ]] || fail "cube.$f missing"; done
  # Input vertices first, with their numbers and coordinates; 1-based like the input.
  sed -n 2p "$work/cube.node" | grep -Eq '^1 0 0 0$' || fail "cube.node: vertex 1 is not (0,0,0)"
  sed -n 9p "$work/cube.node" | grep -Eq '^8 0 1 1$' || fail "cube.node: vertex 8 is not (0,1,1)"
  sed -n 2p "$work/cube.ele" | grep -q '^1 ' || fail "cube.ele: first tetrahedron is not 1"
  # Twelve boundary triangles, two per facet, each with its facet's marker.
  head -n1 "$work/cube.face" | grep -q '^12 1$' || fail "cube.face: expected '12 1': $(head -n1 "$work/cube.face")"
  local marker
  for marker in 1 2 3 4 5 6; do
    [[ $(awk -v m="$marker" 'NR > 1 && $5 == m' "$work/cube.face" | wc -l) -eq 2 ]] ||
      fail "cube.face: facet $marker does not have 2 triangles"
  done
  # The tetrahedra are valid (check accepts a conforming Delaunay mesh of the cube's corners).
  run 0 check "$work/cube.node" "$work/cube.ele" || fail "check rejected cube.ele"
  # An .off: the same cube as 12 triangles, 0-based.
  printf 'OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n' >"$work/cube.off"
  printf '3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n' >>"$work/cube.off"
  run 0 tetmesh "$work/cube.off" -o "$work/off.vtu" || return
  grep -q '<UnstructuredGrid>' "$work/off.vtu" || fail "off.vtu is not a VTK unstructured grid"
  grep -Eq '^tetrahedra: [1-9][0-9]*$' "$work/out" || fail "no tetrahedra line: $(cat "$work/out")"
  # Built-in domains, each format.
  run 0 tetmesh --domain box-with-hole -o "$work/box.msh" || return
  grep -q '^\$MeshFormat' "$work/box.msh" || fail "box.msh is not Gmsh"
  run 0 tetmesh --domain box-with-hole -o "$work/box.ele" --quality || return
  grep -Eq '^min_dihedral_degrees: [0-9.]+$' "$work/out" || fail "--quality: no min_dihedral_degrees"
  # The box's 24 facet triangles: 12 outer (marker 1), 12 around the cavity (marker 2).
  [[ $(awk 'NR > 1 && $5 == 2' "$work/box.face" | wc -l) -eq 12 ]] || fail "box.face: cavity faces"
  run 0 tetmesh --domain ellipsoid --domain-size 0.5 -o "$work/ellipsoid.ele" || return
}

tetmesh_stats() {
  run 0 tetmesh --domain box-with-hole -o "$work/s.ele" --stats || return
  grep -Eq '^construct_seconds: [0-9]+\.[0-9]+$' "$work/out" || fail "--stats: no construct_seconds"
  local name
  for name in segments segment_splits shell_splits encroachment_splits facet_splits insertions rounds removed_tets; do
    grep -Eq "^$name: [0-9]+$" "$work/out" || fail "--stats: no '$name: N' line"
  done
  grep -q '^segments: 24$' "$work/out" || fail "--stats: the box has 24 segments: $(cat "$work/out")"
  grep -q '^removed_tets: [1-9]' "$work/out" || fail "--stats: the cavity's tetrahedra were not removed"
}

tetmesh_duplicates() {
  # Vertices at one point are merged, as TetGen merges them: a cube whose vertex 9 repeats
  # vertex 1, named by one facet instead of it. A warning names both; the .node keeps vertex 9
  # (unused by every tetrahedron), the Steiner points after it; check accepts the mesh.
  write_cube_poly "$work/cube.poly"
  sed -e 's/^8 3 0 0$/9 3 0 0/' -e 's/^8 0 1 1$/8 0 1 1\n9 0 0 0/' -e 's/^4 1 2 3 4$/4 9 2 3 4/' \
    "$work/cube.poly" >"$work/dup.poly"
  run 0 tetmesh "$work/dup.poly" --max-volume 0.05 -o "$work/dup.ele" || return
  grep -Eq '^exactmesh: warning: .*dup\.poly: 1 vertex at the same point as an earlier one merged into it.*: 9 into 1 \(0, 0, 0\)' "$work/err" ||
    fail "no merge warning for dup.poly: $(cat "$work/err")"
  sed -n 10p "$work/dup.node" | grep -Eq '^9 0 0 0$' || fail "dup.node: vertex 9 is not (0,0,0)"
  [[ $(head -n1 "$work/dup.node" | awk '{print $1}') -gt 9 ]] || fail "dup.node: no Steiner point"
  awk 'NR > 1 && !/^#/ && ($2 == 9 || $3 == 9 || $4 == 9 || $5 == 9)' "$work/dup.ele" | grep -q . &&
    fail "dup.ele: a tetrahedron uses the merged vertex 9"
  run 0 check "$work/dup.poly" "$work/dup.ele" || fail "check rejected dup.ele: $(cat "$work/out")"
  # An .off whose faces each have their own four corners (24 vertices, a cube split at its
  # seams, as exported meshes often are): meshed, and checked.
  local f c
  printf 'OFF\n24 6 0\n' >"$work/seams.off"
  for f in '0 0 0 1 0 0 1 1 0 0 1 0' '0 0 1 0 1 1 1 1 1 1 0 1' '0 0 0 0 0 1 1 0 1 1 0 0' \
           '1 0 0 1 0 1 1 1 1 1 1 0' '1 1 0 1 1 1 0 1 1 0 1 0' '0 1 0 0 1 1 0 0 1 0 0 0'; do
    echo "$f" | awk '{for (i = 1; i <= 12; i += 3) print $i, $(i + 1), $(i + 2)}' >>"$work/seams.off"
  done
  for c in 0 4 8 12 16 20; do echo "4 $c $((c + 1)) $((c + 2)) $((c + 3))" >>"$work/seams.off"; done
  run 0 tetmesh "$work/seams.off" --max-volume 0.05 -o "$work/seams.ele" || return
  grep -q '16 vertices at the same point' "$work/err" || fail "seams.off: $(cat "$work/err")"
  run 0 check "$work/seams.off" "$work/seams.ele" || fail "check rejected seams.ele: $(cat "$work/out")"
  # A triangle with two corners at one point (as an exported STL's or OFF's) has no area: left
  # out, with its line.
  printf 'OFF\n8 13 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n' >"$work/c.off"
  printf '3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n3 0 1 1\n' >>"$work/c.off"
  run 0 tetmesh "$work/c.off" -o "$work/c.ele" || return
  grep -Eq 'c\.off: 1 facet with no area \(corners at fewer than three points\) left out: facet 12 \(line 23\)' "$work/err" ||
    fail "no zero-area warning for c.off: $(cat "$work/err")"
  run 0 check "$work/c.off" "$work/c.ele" || fail "check rejected c.ele: $(cat "$work/out")"
  # A triangle written twice (the other way round the second time): left out, naming both.
  sed -e 's/^3 0 1 1$/3 7 6 4/' "$work/c.off" >"$work/twice.off"
  run 0 tetmesh "$work/twice.off" -o "$work/twice.ele" || return
  grep -Eq 'twice\.off: 1 facet repeating an earlier one left out: facet 12 \(line 23\) repeats facet 3 \(line 14\)' "$work/err" ||
    fail "no repeated-facet warning for twice.off: $(cat "$work/err")"
  run 0 check "$work/twice.off" "$work/twice.ele" || fail "check rejected twice.ele: $(cat "$work/out")"
}

tetmesh_bad_input() {
  write_cube_poly "$work/cube.poly"
  # A facet naming a vertex the file lacks: the reader's file:line message, exit 2.
  sed 's/^4 5 6 7 8$/4 5 6 7 9/' "$work/cube.poly" >"$work/bad.poly"
  expect_error 2 'bad\.poly:[0-9]+: .*9' tetmesh "$work/bad.poly" -o "$work/x.ele"
  printf 'OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 nan\n3 0 1 2\n' >"$work/nan.off"
  expect_error 2 'nan\.off:[0-9]+: ' tetmesh "$work/nan.off" -o "$work/x.ele"
  # An open surface (one facet missing): the PLC check refuses it.
  printf 'OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n' >"$work/open.off"
  expect_error 2 'open\.off: surface not closed: .*facet 0 \(line 7\)' tetmesh "$work/open.off" -o "$work/x.ele"
  # A non-planar facet (a corner lifted off its plane): split into triangles with a warning
  # naming the file, the facet's line and the vertex off its plane; the mesh passes its check.
  sed 's/^3 1 1 0$/3 1 1 0.125/' "$work/cube.poly" >"$work/bent.poly"
  run 0 tetmesh "$work/bent.poly" --max-volume 0.05 -o "$work/bent.ele" || return
  grep -Eq '^exactmesh: warning: .*bent\.poly: facet 1 \(line [0-9]+\) is not planar \(vertex [0-9]+ is off the plane of vertices .*\): split into the 2 triangles' "$work/err" ||
    fail "no split warning for bent.poly: $(cat "$work/err")"
  # Rotated unit cubes (every facet an ulp off its plane): kept whole (within rounding of a
  # plane), meshed with no warning and checked exactly.
  local k
  for k in 1 2 3 4 5 11; do
    run 0 tetmesh "$data/rotated/cube_$k.poly" --max-volume 0.0005 -o "$work/rot.ele" || return
    [ ! -s "$work/err" ] || fail "warnings for rotated cube_$k: $(cat "$work/err")"
  done
  # cube_11 at --radius-edge 2 ended with an internal error (exit 3) when its facets were split
  # (a circumcentre whose cavity could not keep its tetrahedron went in anyway); whole, it
  # meshes with every tetrahedron within the bound.
  run 0 tetmesh "$data/rotated/cube_11.poly" --radius-edge 2 -o "$work/rot.ele" || return
  [ ! -s "$work/err" ] || fail "warnings for cube_11: $(cat "$work/err")"
  # Facets at 45 degrees (a triangular prism, issue 15): their subfaces encroached each
  # other into the Steiner budget. Facets meeting below 60 degrees are sharp now: no splits
  # between them, the tetrahedra at their segment spared (and checked so, exactly).
  printf 'OFF\n6 5 0\n0 0 0\n1 0 0\n1 1 0\n0 0 1\n1 0 1\n1 1 1\n3 0 2 1\n3 3 4 5\n4 0 1 4 3\n4 1 2 5 4\n4 2 0 3 5\n' >"$work/wedge.off"
  run 0 tetmesh "$work/wedge.off" --max-volume 0.01 --max-steiner 100000 --stats -o "$work/wedge.ele" || return
  grep -Eq '^vertices: [0-9]{1,3}$' "$work/out" || fail "wedge: too many vertices: $(cat "$work/out")"
  run 0 tetmesh "$work/wedge.off" --max-volume 0.01 --radius-edge 1.2 --stats --quality -o "$work/wedge.ele" || return
  grep -Eq '^spared_small_angle_tets: [1-9]' "$work/out" || fail "wedge: nothing spared: $(cat "$work/out")"
  # Lifted so far that the facet's projection crosses itself: refused, naming the facet.
  sed 's/^3 1 1 0$/3 -1 -1 0.5/' "$work/cube.poly" >"$work/twisted.poly"
  expect_error 2 'twisted\.poly: .*facet [0-9]+ \(line [0-9]+\)' tetmesh "$work/twisted.poly" -o "$work/x.ele"
  # Numbers CLI11's own check lets through (nan) or names with 300 digits (0).
  expect_error 2 "--max-volume: 'nan' is not a finite number > 0" tetmesh --domain box-with-hole --max-volume nan -o "$work/x.ele"
  expect_error 2 "--radius-edge: '0' is not a finite number > 0" tetmesh --domain box-with-hole --radius-edge 0 -o "$work/x.ele"
  expect_error 2 "--domain-size: 'inf' is not a finite number > 0" tetmesh --domain ellipsoid --domain-size inf -o "$work/x.ele"
  # A surface sampling finer than 10^6 vertices is refused at once with its estimate.
  expect_error 2 'ellipsoid: a surface size of 1e-300 asks for far more than 1e300' tetmesh --domain ellipsoid --domain-size 1e-300 -o "$work/x.ele"
  expect_error 2 'wing: a surface size of 1e-07 asks for about 4.08e\+07 surface vertices' tetmesh --domain wing --domain-size 1e-7 -o "$work/x.ele"
  expect_error 2 'moon' tetmesh --domain moon -o "$work/x.ele"
  expect_error 2 'not both' tetmesh "$work/cube.poly" --domain box-with-hole -o "$work/x.ele"
  expect_error 2 'not both' tetmesh -o "$work/x.ele"
  expect_error 2 '2D only' tetmesh "$work/cube.poly" -o "$work/x.svg"
  printf 'solid x\n' >"$work/x.txt"
  expect_error 2 'x\.txt' tetmesh "$work/x.txt" -o "$work/x.ele"
  [[ ! -e "$work/x.ele" ]] || fail "x.ele written for bad input"
}

tetmesh_refine() {
  write_cube_poly "$work/cube.poly"
  # Radius-edge and volume bounds: counters, the exact check's counts, more tetrahedra.
  run 0 tetmesh "$work/cube.poly" -o "$work/q.ele" --radius-edge 1.2 --max-volume 0.01 --stats --quality || return
  local name
  for name in refinement_circumcenters refinement_subface_splits refinement_segment_splits \
    refinement_rejected_points refinement_insertions spared_small_angle_tets over_bound_tets; do
    grep -Eq "^$name: [0-9]+$" "$work/out" || fail "--stats: no '$name: N' line"
  done
  grep -q '^over_bound_tets: 0$' "$work/out" || fail "cube: tetrahedra over the bounds: $(cat "$work/out")"
  grep -Eq '^construct_seconds: [0-9]+\.[0-9]+$' "$work/out" || fail "--stats: no construct_seconds"
  [[ $(head -n1 "$work/q.ele" | awk '{print $1}') -ge 100 ]] || fail "q.ele: fewer than 100 tetrahedra"
  awk '/^max_radius_edge:/ { exit !($2 <= 1.2) }' "$work/out" || fail "--quality: max_radius_edge over 1.2"
  # The radius-edge histogram agrees with the bound: no ratio over 1.2, so nothing from [1.2, 1.4) on.
  grep -q '^radius_edge_over_2: 0$' "$work/out" || fail "--quality: radius_edge_over_2 not 0"
  awk -F'[][,):]+' '/^radius_edge\[/ && $2 >= 1.2 && $NF != " 0" { bad = 1 } END { exit bad }' "$work/out" ||
    fail "--quality: radius-edge ratios of 1.2 and more counted: $(grep '^radius_edge' "$work/out")"
  # Input vertices keep their numbers; Steiner points follow them.
  sed -n 2,9p "$work/q.node" | awk '{print $2, $3, $4}' | tr '\n' ' ' |
    grep -q '^0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1 $' || fail "q.node: input vertices moved"
  # Every boundary triangle still carries its facet's marker (1..6).
  awk 'NR > 1 && ($5 < 1 || $5 > 6)' "$work/q.face" | grep -q . && fail "q.face: a face without its marker"
  run 0 tetmesh --domain box-with-hole -o "$work/box.vtu" --radius-edge 2 --stats || return
  grep -q '^over_bound_tets: 0$' "$work/out" || fail "box-with-hole: tetrahedra over the bound"
  # Refinement then sliver removal (on by default): its counters, the quality before and after.
  run 0 tetmesh --domain box-with-hole --max-volume 0.0025 -o "$work/r.ele" --stats --quality || return
  for name in flips_32 moves_accepted slivers_before slivers_after; do
    grep -Eq "^sliver_removal_$name: [0-9]+$" "$work/out" || fail "--stats: no 'sliver_removal_$name: N' line"
  done
  grep -Eq '^sliver_removal_slivers_before: [1-9]' "$work/out" || fail "sliver removal found no sliver"
  grep -q '^sliver_removal_slivers_after: 0$' "$work/out" || fail "slivers left: $(cat "$work/out")"
  grep -Eq '^before_sliver_removal_dihedral_degrees\[0,10\): [1-9]' "$work/out" ||
    fail "--quality: no angle below 10 degrees before sliver removal"
  grep -q '^dihedral_degrees\[0,10): 0$' "$work/out" || fail "--quality: angles below 10 degrees left"
  run 0 tetmesh --domain box-with-hole --max-volume 0.0025 -o "$work/n.ele" --stats --no-sliver-removal || return
  grep -q '^sliver_removal_' "$work/out" && fail "--no-sliver-removal still printed sliver removal counters"
  grep -Eq '^over_bound_tets: 0$' "$work/out" || fail "box-with-hole: tetrahedra over the bounds"
  # Bad bounds are usage errors; the budget is an input error naming it.
  expect_error 2 'radius-edge' tetmesh "$work/cube.poly" -o "$work/x.ele" --radius-edge -1
  expect_error 2 'max-volume' tetmesh "$work/cube.poly" -o "$work/x.ele" --max-volume 0
  expect_error 2 'budget of 20 exceeded' tetmesh "$work/cube.poly" -o "$work/x.ele" --max-volume 1e-5 --max-steiner 20
  [[ ! -e "$work/x.ele" ]] || fail "x.ele written for bad input"
}

# Two unit cubes side by side (an internal facet at x = 1), TetGen's region list with a volume
# bound per region: write_two_regions_poly FILE LEFT_BOUND RIGHT_BOUND.
write_two_regions_poly() {
  local file=$1 left_bound=$2 right_bound=$3
  {
    printf '# two unit cubes, an internal facet at x = 1, two regions\n12 3 0 0\n'
    local i=1 x y z
    for z in 0 1; do for y in 0 1; do for x in 0 1 2; do
      printf '%d %d %d %d\n' "$i" "$x" "$y" "$z"; i=$((i + 1))
    done; done; done
    printf '11 1\n'
    local f
    for f in '1 4 10 7 1' '2 5 11 8 3' '3 6 12 9 2' '1 2 8 7 1' '2 3 9 8 1' '4 5 11 10 1' \
      '5 6 12 11 1' '1 2 5 4 1' '2 3 6 5 1' '7 8 11 10 1' '8 9 12 11 1'; do
      set -- $f
      printf '1 0 %d\n4 %d %d %d %d\n' "$5" "$1" "$2" "$3" "$4"
    done
    printf '0\n2\n1 0.5 0.5 0.5 1 %s\n2 1.5 0.5 0.5 2 %s\n' "$left_bound" "$right_bound"
  } >"$file"
}

# region_volumes NODE ELE: "<tets left> <tets right> <largest volume left> <largest right>", the
# side by the centroid's x (rounded volumes: a report, the exact check is the command's own).
region_volumes() {
  awk 'FNR == 1 || /^#/ { next }
    FILENAME ~ /node$/ { X[$1] = $2; Y[$1] = $3; Z[$1] = $4; next }
    { a = $2; b = $3; c = $4; d = $5
      ux = X[b] - X[a]; uy = Y[b] - Y[a]; uz = Z[b] - Z[a]
      vx = X[c] - X[a]; vy = Y[c] - Y[a]; vz = Z[c] - Z[a]
      wx = X[d] - X[a]; wy = Y[d] - Y[a]; wz = Z[d] - Z[a]
      v = (ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)) / 6
      if (v < 0) v = -v
      k = (X[a] + X[b] + X[c] + X[d]) / 4 < 1 ? 0 : 1
      n[k]++; if (v > m[k]) m[k] = v }
    END { printf "%d %d %.17g %.17g\n", n[0], n[1], m[0], m[1] }' "$1" "$2"
}

# region_attributes_match NODE ELE LEFT RIGHT: the .ele carries one attribute column (header
# "#T 4 1") and each tetrahedron's attribute is LEFT when its centroid's x is below 1, else RIGHT
# (the centroid of a tetrahedron with corners on either side of the cut at x = 1 could not be
# told apart: none may exist, as each region's tetrahedra lie on its side).
region_attributes_match() {
  awk -v left="$3" -v right="$4" 'FNR == 1 && FILENAME !~ /node$/ { if ($3 != 1) bad = 1 }
    FNR == 1 || /^#/ { next }
    FILENAME ~ /node$/ { X[$1] = $2; next }
    { n++; want = (X[$2] + X[$3] + X[$4] + X[$5]) / 4 < 1 ? left : right
      if (NF != 6 || $6 != want) bad = 1 }
    END { exit bad || n == 0 }' "$1" "$2"
}

tetmesh_regions() {
  # Region volume bounds (TetGen's -a with region constraints): refinement runs without
  # --max-volume, each region within its own bound, checked exactly before writing.
  write_two_regions_poly "$work/two.poly" 0.001 0.01
  run 0 tetmesh "$work/two.poly" -o "$work/r.ele" --stats || return
  grep -Eq '^refinement_insertions: [1-9][0-9]*$' "$work/out" || fail "region bounds: no refinement: $(cat "$work/out")"
  grep -q '^over_bound_tets: 0$' "$work/out" || fail "region bounds: tetrahedra over them: $(cat "$work/out")"
  local left right left_max right_max
  read -r left right left_max right_max < <(region_volumes "$work/r.node" "$work/r.ele")
  awk -v m="$left_max" 'BEGIN { exit !(m <= 0.001 * (1 + 1e-9)) }' || fail "left region: a tetrahedron of volume $left_max"
  awk -v m="$right_max" 'BEGIN { exit !(m <= 0.01 * (1 + 1e-9)) }' || fail "right region: a tetrahedron of volume $right_max"
  [[ $left -gt $((4 * right)) ]] || fail "the fine region has $left tetrahedra, the coarse one $right"
  # A global bound applies on top: the smaller of the two in each region.
  run 0 tetmesh "$work/two.poly" -o "$work/g.ele" --max-volume 0.004 --stats || return
  grep -q '^over_bound_tets: 0$' "$work/out" || fail "global + region bounds: tetrahedra over them"
  read -r left right left_max right_max < <(region_volumes "$work/g.node" "$work/g.ele")
  awk -v m="$right_max" 'BEGIN { exit !(m <= 0.004 * (1 + 1e-9)) }' || fail "--max-volume 0.004: a right tetrahedron of volume $right_max"
  awk -v m="$left_max" 'BEGIN { exit !(m <= 0.001 * (1 + 1e-9)) }' || fail "--max-volume 0.004: a left tetrahedron of volume $left_max"
  # Frontal insertion follows --size and says it ignores the region bounds.
  run 0 tetmesh "$work/two.poly" --generator frontal --size 0.3 -o "$work/f.ele" || return
  grep -q 'warning: .*region volume bounds are applied by Delaunay refinement only' "$work/err" ||
    fail "frontal: no warning about the region bounds: $(cat "$work/err")"
  # Every generator writes the region attribute column (TetGen -A), each tetrahedron its side's.
  region_attributes_match "$work/r.node" "$work/r.ele" 1 2 || fail "refinement: r.ele's region attributes"
  region_attributes_match "$work/f.node" "$work/f.ele" 1 2 || fail "frontal: f.ele's region attributes"
  # The octree takes each region's bound as a size (the regular tetrahedron's edge): the
  # finer-bounded cube gets more tetrahedra, each on its side; those over their bound counted.
  run 0 tetmesh "$work/two.poly" --generator octree --size 0.3 --stats -o "$work/ob.ele" || return
  grep -Eq '^over_region_bound_tets: [0-9]+$' "$work/out" || fail "octree: no over_region_bound_tets line"
  region_attributes_match "$work/ob.node" "$work/ob.ele" 1 2 || fail "octree bounds: ob.ele's region attributes"
  read -r left right left_max right_max < <(region_volumes "$work/ob.node" "$work/ob.ele")
  [[ $left -ge 1000 && $left -gt $((2 * right)) ]] || fail "octree bounds: $left tetrahedra left (bound 0.001), $right right"
  run 0 check "$work/two.poly" "$work/ob.ele" && grep -q '^ok: ' "$work/out" || fail "check two.poly ob.ele: $(cat "$work/out")"
  write_two_regions_poly "$work/plain.poly" -1 -1
  run 0 tetmesh "$work/plain.poly" --generator octree --size 0.1 --stats -o "$work/o.ele" || return
  grep -Eq '^octree_core_leaves: [1-9]' "$work/out" || fail "octree regions: no core leaf"
  region_attributes_match "$work/o.node" "$work/o.ele" 1 2 || fail "octree: o.ele's region attributes: $(head -n3 "$work/o.ele")"
  run 0 check "$work/plain.poly" "$work/o.ele" &&
    grep -Eq '^ok: [0-9]+ tetrahedra, exact conforming mesh of the PLC' "$work/out" ||
    fail "check plain.poly o.ele: $(cat "$work/out")"
  # A region bound far over the budget is refused at once with the estimate.
  write_two_regions_poly "$work/tiny.poly" 1e-12 0.01
  expect_error 2 'exceeded at once: the region volume bounds \(smallest 1e-12\) ask for about 1\.54e\+11' \
    tetmesh "$work/tiny.poly" -o "$work/x.ele"
  [[ ! -e "$work/x.ele" ]] || fail "x.ele written for a refused bound"
}

tetmesh_frontal() {
  write_cube_poly "$work/cube.poly"
  # Frontal insertion at a uniform size, then sliver removal; the exact conformity check runs
  # before writing. Counters, input vertices kept, edges near the size.
  run 0 tetmesh "$work/cube.poly" --generator frontal --size 0.2 -o "$work/f.ele" --stats --quality || return
  local name
  for name in segment_splits subface_splits interior_points accepted_tets estimated_points; do
    grep -Eq "^frontal_$name: [0-9]+$" "$work/out" || fail "--stats: no 'frontal_$name: N' line"
  done
  grep -Eq '^frontal_interior_points: [1-9]' "$work/out" || fail "frontal: no interior point"
  grep -Eq '^sliver_removal_rounds: [0-9]+$' "$work/out" || fail "frontal: no sliver removal"
  grep -q '^dihedral_degrees\[0,10): 0$' "$work/out" || fail "frontal: angles below 10 degrees left"
  [[ $(head -n1 "$work/f.ele" | awk '{print $1}') -ge 300 ]] || fail "f.ele: fewer than 300 tetrahedra"
  sed -n 2,9p "$work/f.node" | awk '{print $2, $3, $4}' | tr '\n' ' ' |
    grep -q '^0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1 $' || fail "f.node: input vertices moved"
  # --quality's size conformity (edge length / size, each edge once): most edges near the size
  # (measured 92.1% in [0.7, 1.4]).
  awk '/^size_conformity: / { for (i = 1; i <= NF; ++i) if ($i ~ /%$/) share = $i + 0 }
       END { exit !(share >= 85) }' "$work/out" || fail "f: edges far from the size: $(grep size_conformity "$work/out")"
  # A size expression in x, y, z; a built-in domain.
  run 0 tetmesh --domain ellipsoid --domain-size 0.3 --generator frontal --size '0.15 + 0.1 * abs(z)' -o "$work/e.vtu" || return
  # The generator's name, the size's presence and kind are checked before any work.
  expect_error 2 'delaunay-refinement, frontal, octree' tetmesh "$work/cube.poly" --generator quadtree --size 0.2 -o "$work/x.ele"
  expect_error 2 'needs --size' tetmesh "$work/cube.poly" --generator frontal -o "$work/x.ele"
  expect_error 2 'is for --generator frontal' tetmesh "$work/cube.poly" --size 0.2 -o "$work/x.ele"
  expect_error 2 'takes --size' tetmesh "$work/cube.poly" --generator frontal --size 0.2 --max-volume 0.1 -o "$work/x.ele"
  expect_error 2 'feature-gradation must be a finite number >= 0, not -1' tetmesh "$work/cube.poly" --generator frontal --size 0.2 --feature-gradation -1 -o "$work/x.ele"
  expect_error 2 'feature-gradation is for --generator frontal or octree' tetmesh "$work/cube.poly" --feature-gradation 0.5 -o "$work/x.ele"
  expect_error 2 'expression in x, y and z' tetmesh "$work/cube.poly" --generator frontal --size 'w + 1' -o "$work/x.ele"
  expect_error 2 'budget of 1000 exceeded at once: the size uniform 0.001 asks for about' \
    tetmesh "$work/cube.poly" --generator frontal --size 0.001 --max-steiner 1000 -o "$work/x.ele"
  [[ ! -e "$work/x.ele" ]] || fail "x.ele written for bad input"
}

tetmesh_octree() {
  # The octree generator on the built-in box-with-hole: core leaves cut by templates, the band
  # meshed by recovery and frontal insertion, sliver removal after; the exact conformity check
  # runs before writing. Counters, input vertices kept and numbered first, facet markers.
  run 0 tetmesh --domain box-with-hole --generator octree --size 0.06 --stats -o "$work/o.ele" || return
  local name
  for name in leaves balance_splits core_leaves core_components interface_facets band_tets template_tets estimated_leaves; do
    grep -Eq "^octree_$name: [0-9]+$" "$work/out" || fail "--stats: no 'octree_$name: N' line"
  done
  grep -Eq '^octree_core_leaves: [1-9]' "$work/out" || fail "octree: no core leaf"
  grep -Eq '^octree_template_tets: [1-9]' "$work/out" || fail "octree: no template tetrahedron"
  grep -Eq '^octree_band_frontal_accepted_tets: [1-9]' "$work/out" || fail "octree: no band frontal counters"
  grep -Eq '^sliver_removal_rounds: [0-9]+$' "$work/out" || fail "octree: no sliver removal"
  [[ $(head -n1 "$work/o.ele" | awk '{print $1}') -ge 10000 ]] || fail "o.ele: fewer than 10000 tetrahedra"
  sed -n 2,3p "$work/o.node" | awk '{print $2, $3, $4}' | tr '\n' ' ' |
    grep -q '^0 0 0 1 0 0 $' || fail "o.node: input vertices moved"
  awk 'NR > 1 && $1 !~ /^#/ { m[$5] = 1 } END { exit !(m[1] && m[2]) }' "$work/o.face" || fail "o.face: facet markers 1 and 2 missing"
  # A size expression; a .vtu output.
  run 0 tetmesh --domain ellipsoid --domain-size 0.15 --generator octree --size '0.08 + 0.05 * abs(x)' -o "$work/e.vtu" || return
  # Errors before any work: no size, a bad size, the leaf budget.
  expect_error 2 'needs --size' tetmesh --domain box-with-hole --generator octree -o "$work/x.ele"
  expect_error 2 'takes --size' tetmesh --domain box-with-hole --generator octree --size 0.1 --max-volume 0.1 -o "$work/x.ele"
  expect_error 2 'size' tetmesh --domain box-with-hole --generator octree --size 0 -o "$work/x.ele"
  expect_error 2 'size' tetmesh --domain box-with-hole --generator octree --size=-0.1 -o "$work/x.ele"
  expect_error 2 'leaf budget of 1000000 exceeded at once' tetmesh --domain box-with-hole --generator octree --size 0.001 -o "$work/x.ele"
  [[ ! -e "$work/x.ele" ]] || fail "x.ele written for bad input"
}

tetmesh_check() {
  write_cube_poly "$work/cube.poly"
  # Every generator's mesh of the cube is checked exactly against the PLC: ok, exit 0.
  local args
  for args in "--radius-edge 2" "--generator frontal --size 0.3" "--generator octree --size 0.3"; do
    # shellcheck disable=SC2086
    run 0 tetmesh "$work/cube.poly" -o "$work/c.ele" $args || return
    run 0 check "$work/cube.poly" "$work/c.ele" &&
      grep -Eq '^ok: [0-9]+ tetrahedra, exact conforming mesh of the PLC' "$work/out" ||
      fail "check cube.poly c.ele ($args): $(cat "$work/out")"
  done
  # A tetrahedron left out: its faces are no facet pieces; exit 1 naming the problem.
  awk 'NR == 1 { print $1 - 1, $2, $3; next } NR == 2 { next } { $1 = $1 - 1; print }' "$work/c.ele" >"$work/d.ele"
  cp "$work/c.node" "$work/d.node"
  cp "$work/c.face" "$work/d.face"
  run 1 check "$work/cube.poly" "$work/d.ele" &&
    grep -q '^not ok: ' "$work/out" || fail "check of a mesh with a tetrahedron left out: $(cat "$work/out")"
  # No .node beside the .ele: one clear error.
  cp "$work/c.ele" "$work/lonely.ele"
  expect_error 2 'lonely.node: no such file' check "$work/cube.poly" "$work/lonely.ele"
}

# The hostile-file campaign of 2026-12-06 (scripts/hostile_files.py, tests/data/hostile_files):
# each finding's input, fixed. /dev/zero as an .stl fails at its first line, without reading
# 1 GB first; a byte order mark starts an ASCII STL and a size file as it starts a .node; a
# size asking for 5e300 boundary pieces is refused at once (it sampled 2^24 points, 3.4 s and
# 400 MB, without --max-steiner); adapt says that it ignores a region's maximum area; check
# --convex-hull passes a correct mesh with holes (it refused it, exit 2, until stop 52, and
# before that failed it); an expression is cut in messages.
hostile_files() {
  local dir=$data/hostile_files
  ln -s /dev/zero "$work/zero.stl"
  expect_error 2 'zero\.stl:1: a NUL byte at column 1' tetmesh "$work/zero.stl" -o "$work/x.ele"
  expect_error 2 'zero\.stl:1: a NUL byte at column 1' check "$work/zero.stl" "$work/x.ele"
  run 0 tetmesh "$dir/cube_ascii_with_bom.stl" -o "$work/bom.ele" || return
  run 0 check "$dir/cube_ascii_with_bom.stl" "$work/bom.ele" || return
  run 0 mesh --domain key --size "$dir/size_with_bom.txt" -o "$work/bom2.ele" || return
  local generator start
  for generator in frontal quadtree advancing-front metric-delaunay; do
    start=$(date +%s%N)
    expect_error 2 'strip_1e300_by_1e-300\.poly: boundary discretization: the size function asks for more than 2\^30 pieces' \
      mesh "$dir/strip_1e300_by_1e-300.poly" --generator "$generator" --size 0.2 -o "$work/x.ele"
    (($(date +%s%N) - start < 1000000000)) || fail "strip, $generator: refused after more than 1 s"
  done
  run 0 adapt "$dir/square_hole_tiny_region_area.poly" --field x --cycles 0 -o "$work/a.ele" || return
  grep -q 'square_hole_tiny_region_area\.poly:23: region maximum areas are not applied (adapt' "$work/err" ||
    fail "adapt: no warning about the region's area: $(cat "$work/err")"
  expect_error 2 'region volume|maximum areas ask for' mesh "$dir/square_hole_tiny_region_area.poly" -o "$work/x.ele"
  run 0 cdt "$dir/square_hole_tiny_region_area.poly" --convex-hull -o "$work/c.ele" || return
  # With hole points --convex-hull checks the hull less the holes (check_hull_cover_2d, stop 52).
  run 0 check "$dir/square_hole_tiny_region_area.poly" "$work/c.ele" --convex-hull || return
  grep -q '^ok: ' "$work/out" || fail "check --convex-hull with a hole: $(cat "$work/out")"
  # A mesh that keeps the hole region (made without the hole point) fails (exit 1), naming an
  # edge of the hole.
  sed -e 's/^1 0\.5 0\.5$//' "$dir/square_hole_tiny_region_area.poly" |
    awk '/^1$/ && !done && seen_segments {print "0"; done = 1; next} /^8 0$/ {seen_segments = 1} {print}' \
      >"$work/no_hole.poly"
  run 0 cdt "$work/no_hole.poly" --convex-hull -o "$work/kept.ele" || return
  run 1 check "$dir/square_hole_tiny_region_area.poly" "$work/kept.ele" --convex-hull
  grep -q 'bounds the convex hull less the holes but not the mesh' "$work/out" ||
    fail "check --convex-hull passed a kept hole: $(cat "$work/out")"
  run 0 check "$dir/square_hole_tiny_region_area.poly" "$work/c.ele" || return
  local long
  long="0.1$(printf '+0%.0s' {1..5000})x"
  expect_error 2 "^exactmesh: error: --size '0\.1\+0\+0.{100,250}' is neither" mesh --domain key --size "$long" -o "$work/x.ele"
  [[ $(wc -c <"$work/err") -lt 1000 ]] || fail "a long expression echoed whole: $(wc -c <"$work/err") bytes"
  [[ ! -e $work/x.ele ]] || fail "x.ele written for bad input"
  # A PSLG without segments is its convex hull for every generator (some refused it as
  # enclosing no region, others meshed the hull), as for cdt; each mesh passes the check.
  for generator in delaunay-refinement frontal quadtree advancing-front advancing-front-delaunay \
    min-max-front metric-delaunay; do
    run 0 mesh "$dir/no_segments.poly" --generator "$generator" --size 0.2 -o "$work/h.ele" || return
    grep -q 'no_segments\.poly: no segments: the domain is the convex hull of the vertices' "$work/err" ||
      fail "no segments, $generator: no warning: $(cat "$work/err")"
    run 0 check "$dir/no_segments.poly" "$work/h.ele" --conforming || return
  done
}

case "$case_name" in
  triangulate_all_algorithms | output_formats | stats | point_location | bad_input | \
    check_rejects_non_delaunay | cdt | mesh | swap_criteria | min_max | swap_bad_input | swap3d_criteria | \
    swap3d_bad_input | tetrahedralize_all | tetrahedralize_formats | tetrahedralize_stats | \
    tetrahedralize_bad_input | check_rejects_non_delaunay_3d | mesh_impossible_sizes | hostile_data_loss | hostile_refuse_inputs | \
    hostile_reading | hostile_holes | hostile_swap_validation | hostile_options | hostile_messages | \
    region_areas | adapt | adapt_bad_input | mesh_metric | mesh_metric_delaunay | layers | omesh | \
    mesh_min_max_front | svg_view | tetmesh | tetmesh_stats | tetmesh_duplicates | tetmesh_bad_input | tetmesh_refine | tetmesh_regions | \
    tetmesh_frontal | tetmesh_octree | tetmesh_check | threads | mesh_threads | hostile_files)
    "$case_name" ;;
  *)
    echo "unknown case '$case_name'" >&2
    exit 2 ;;
esac
if ((failures > 0)); then
  echo "$case_name: $failures failure(s)" >&2
  exit 1
fi
echo "$case_name: ok"
