#!/bin/bash
# Unpack the bundle of make-bundle.sh and run the GPU benchmarks of `make bench-gpu` (and the EGL tests) with
# it, on a machine without our Debian packages: only glibc (>= BUILD-INFO's), a GPU driver with EGL (NVIDIA's
# libEGL_nvidia, found through __EGL_VENDOR_LIBRARY_FILENAMES) and, for compare_maps.py, python3 with numpy
# and Pillow. Run from the repository root (the scenes and scenes/data are read from there):
#   tools/gpu-bundle/run-on-gpu.sh TARBALL OUTDIR
# Writes OUTDIR/run.log (everything printed) and OUTDIR/gpu-results.tar.gz (every result file, repacked
# after each step, so a run cut short still returns what it finished).
# For a quick trial: WALKING="skirt:672" BENCH_FILTER='^render/(egl|cpu)/float/320$' REPETITIONS=1 (and
# VARIANTS, default "stable ahead papers-ahead": the walking runs' variants, step 3; COLLIDERS, default
# "is-egl is-cpu": theirs; GL_TIMER=0 skips step 5; STEPS, default "maps tests map-render walking determinism
# gl-timer": the steps to run).
set -uo pipefail
TARBALL=${1:?usage: run-on-gpu.sh TARBALL OUTDIR}
OUTDIR=${2:?usage: run-on-gpu.sh TARBALL OUTDIR}
REPO=$(pwd)
WORK=${WORK:-/tmp/clothbench-gpu}
HERE=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$OUTDIR" "$WORK"
R=$WORK/results && rm -rf "$R" && mkdir -p "$R"
exec > >(tee -a "$OUTDIR/run.log") 2>&1
tar -C "$WORK" -xJf "$TARBALL" || exit 1
B=$WORK/clothbench-gpu

# our libraries first, then the NVIDIA driver's folders (libEGL_nvidia.so.0 and what it loads)
export LD_LIBRARY_PATH=$B/lib:/usr/local/nvidia/lib64:/usr/local/nvidia/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
# libstdc++: the host's when it is at least as new as ours (GLIBCXX_3.4.30, GCC 12), else the carried one
LDCONFIG=$(command -v ldconfig || echo /sbin/ldconfig)
host_cxx=$("$LDCONFIG" -p | awk '/libstdc\+\+\.so\.6 .*x86-64/{print $NF; exit}')
if [ -n "$host_cxx" ] && grep -aq GLIBCXX_3.4.30 "$host_cxx"; then cxx="host's $host_cxx"
else export LD_LIBRARY_PATH=$B/lib/cxx:$LD_LIBRARY_PATH; cxx="carried (host: ${host_cxx:-none})"; fi
# glvnd's libEGL (carried) finds NVIDIA's EGL through its vendor file
nv_json=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && [ -f "$nv_json" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$nv_json; fi
export CLOTHBENCH_DATA=$REPO/scenes/data
# scenes name garment files relative to the build's source folder (BUILD-INFO's source_dir): point it here
src=$(sed -n 's/^source_dir: //p' "$B/BUILD-INFO")
if [ -n "$src" ] && [ ! -e "$src/scenes" ]; then mkdir -p "$(dirname "$src")" && ln -sfn "$REPO" "$src"; fi
WALKING=${WALKING-skirt:672 dress_sleeves:2300}
VARIANTS=${VARIANTS-stable ahead papers-ahead}
COLLIDERS=${COLLIDERS-is-egl is-cpu}
BENCH_FILTER=${BENCH_FILTER:-^(render|query)/(egl|cpu)/}
GL_TIMER=${GL_TIMER-1}
STEPS=${STEPS-maps tests map-render walking determinism gl-timer}
want() { [[ " $STEPS " == *" $1 "* ]]; }
REPETITIONS=${REPETITIONS:-3}
CB=$B/bin/clothbench
BODY=$REPO/scenes/data/body/mh_female_walk.glb

pack() { tar -C "$WORK" -czf "$OUTDIR/gpu-results.tar.gz" results; }
step() {  # step NAME COMMAND...: run, print and record its exit status
  local name=$1; shift
  echo "=== $name: $*"
  local t0=$(date +%s%N)
  "$@"; local rc=$?
  echo "=== $name: exit $rc, $(( ($(date +%s%N) - t0) / 1000000 )) ms"
  echo "$name $rc" >> "$R/exit-codes.txt"
  pack
}

{
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "uname: $(uname -a)"
  echo "os: $(. /etc/os-release 2>/dev/null; echo "${PRETTY_NAME:-?}")"
  echo "glibc: $(ldd --version | head -1)"
  echo "libstdc++: $cxx"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2-) x $(nproc)"
  echo "LD_LIBRARY_PATH=$LD_LIBRARY_PATH"
  echo "__EGL_VENDOR_LIBRARY_FILENAMES=${__EGL_VENDOR_LIBRARY_FILENAMES:-}"
  echo "--- nvidia-smi -L"; nvidia-smi -L
  echo "--- nvidia-smi --query-gpu"
  nvidia-smi --query-gpu=name,driver_version,pci.bus_id,memory.total,clocks.max.sm,clocks.max.mem --format=csv
  echo "--- EGL/GL libraries of the driver"; ls /usr/local/nvidia/lib64 2>/dev/null | grep -Ei 'egl|glsi|glcore|tls' || true
  echo "--- EGL vendor file"; cat "${__EGL_VENDOR_LIBRARY_FILENAMES:-/dev/null}"; ls /usr/share/glvnd/egl_vendor.d 2>/dev/null
  echo "--- devices"; ls /dev/nvidia* /dev/dri 2>&1 | tr '\n' ' '; echo
  echo "--- ldd (every library resolved?)"; ldd "$B"/bin/* | grep -E 'not found|=>' | sort -u -k1,1
  echo "--- BUILD-INFO"; cat "$B/BUILD-INFO"
} > "$R/environment.txt" 2>&1
cat "$R/environment.txt"; pack

# 1. the maps, drawn by EGL (its device printed) and by the CPU rasteriser: rest pose and walking at 2 s, two sizes
maps() {
  for pose in rest walk; do
    [ $pose = rest ] && at=() || at=(--animation walk_07_01 --at 2.0)
    for size in 320 1024; do for r in egl cpu; do
      "$CB" maps "$BODY" --renderer $r --size $size "${at[@]}" --png "$R/maps/$pose-$size-$r" || return
    done; done
  done
}
if want maps; then
  step maps maps 2>&1 | tee "$R/maps.txt"
  python3 "$HERE/compare_maps.py" "$R/maps" > "$R/maps-compare.json" 2> "$R/maps-compare.err" || cat "$R/maps-compare.err"
  pack
fi

# 4 (cheap, so early). the EGL tests: EGL against the CPU rasteriser, bit for bit (OSMesa comparisons skip here),
# and the answers of the maps kept on the device against the CPU's from the same maps
want tests && step tests "$B/bin/collide_is_tests" --gtest_filter='EglMaps.*:ImageSpaceAccuracy.Egl*:EglQueries.*' \
  --gtest_output=json:"$R/collide_is_tests.json" 2>&1 | tee "$R/collide_is_tests.txt"

# 2. map rendering per renderer and size, and query batches (`make bench-gpu`; GL rows need OSMesa, not in this build)
want map-render && step map-render "$B/bin/collide_is_bench" --benchmark_filter="$BENCH_FILTER" --benchmark_repetitions=$REPETITIONS \
  --benchmark_out="$R/map-render.json" --benchmark_out_format=json 2>&1 | tee "$R/map-render.txt"

# 3. the walking runs of `make bench-gpu`: skirt (672 v) and dress with sleeves (2300 v), is-egl and is-cpu, in the
# variants of VARIANTS (file suffix): the scene as it is (stable regime; none), the next frame skinned and its maps
# drawn on a second thread while the cloth steps (-ahead), that with the colliders' body simplified to 6,000
# triangles (-ahead-proxy: fewer triangles to draw; the oracle keeps the exact body), and walking-t2's speed row:
# the papers' clock with walking Eq. 5's limit, its passes stopping at 0.05 mm, prepared ahead (-papers-ahead)
variant_sets() {
  case $1 in
    stable) ;;
    ahead) echo --set body.prepare_ahead=true ;;
    ahead-proxy) echo --set body.prepare_ahead=true --set body.collision_triangles=6000 ;;
    papers-ahead) echo --set solver.regime=papers --set solver.limit=velocity --set solver.limit_tolerance_mm=0.05 \
      --set body.prepare_ahead=true ;;
  esac
}
want walking && for gv in $WALKING; do for v in $VARIANTS; do for c in $COLLIDERS; do
  g=${gv%:*}; n=walking-$g-$c; [ $v = stable ] || n=$n-$v
  step $n "$CB" run "$REPO/scenes/walking/$g.toml" --collider $c --set garment.vertices=${gv#*:} $(variant_sets $v) \
    --every-frame --quiet --json "$R/$n.json" 2>&1 | tee "$R/$n.txt"
done; done; done

# 6. determinism on the device: the skirt's walk with is-egl twice, and with the next frame prepared ahead (its maps
# drawn in the second context), each exported as glTF (the cloth's positions at every kept frame): the same bytes
determinism() {
  local g=$R/determinism && mkdir -p "$g"
  for n in first second ahead; do
    local more=() && [ $n = ahead ] && more=(--set body.prepare_ahead=true)
    "$CB" run "$REPO/scenes/walking/skirt.toml" --collider is-egl --set garment.vertices=672 "${more[@]}" --quiet \
      --gltf "$g/$n.glb" --json "$g/$n.json" > "$g/$n.txt" || return
  done
  sha256sum "$g"/*.glb | tee "$g/sha256.txt"
  cmp "$g/first.glb" "$g/second.glb" && cmp "$g/first.glb" "$g/ahead.glb" && echo "determinism: the same bytes"
}
want determinism && step determinism determinism 2>&1 | tee "$R/determinism.txt"

# 5. where is-egl's time goes: the same EGL work once more with gl_timer.c preloaded (time inside glReadPixels =
# waiting for the GPU's drawing + the read-back; per frame), appended to gl-timer.jsonl
export GL_TIMER_LOG=$R/gl-timer.jsonl
timed() { GL_TIMER_LABEL=$1 LD_PRELOAD=$B/preload/libcb_gl_timer.so "${@:2}"; }
gl_timer() {
  for enc in float 8bit; do for size in 320 512 1024; do
    timed "render/egl/$enc/$size" "$B/bin/collide_is_bench" --benchmark_filter="^render/egl/$enc/$size\$" \
      --benchmark_out="$R/gl-timer-render-egl-$enc-$size.json" --benchmark_out_format=json || return
  done; done
  for gv in $WALKING; do
    g=${gv%:*}
    timed "walking-$g-is-egl" "$CB" run "$REPO/scenes/walking/$g.toml" --collider is-egl --set garment.vertices=${gv#*:} \
      --quiet --json "$R/gl-timer-walking-$g-is-egl.json" || return
  done
}
{ [ "$GL_TIMER" = 0 ] || ! want gl-timer; } || step gl-timer gl_timer 2>&1 | tee "$R/gl-timer.txt"
echo "=== done"; cat "$R/exit-codes.txt"; pack
