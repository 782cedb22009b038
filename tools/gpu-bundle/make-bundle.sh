#!/bin/bash
# Build clothbench for a GPU machine that has none of our Debian packages, and pack a portable bundle:
# the three programs the GPU benchmarks need and every shared library they load (ldd), except the C
# library itself. libstdc++/libgcc_s go to lib/cxx/, used there only when the host's are older.
# Run on Debian 12 from the repository root:  tools/gpu-bundle/make-bundle.sh [BUILD_DIR] [TARBALL]
# Defaults: build-gpu (ignored by .gitignore) and .gpu-bundle/clothbench-gpu.tar.xz (add /.gpu-bundle/ to
# .git/info/exclude; the tarball then travels with `carry`, about 15 MB).
# It builds the committed code (git archive of COMMIT, default HEAD, into BUILD_DIR/src), not the work tree.
set -euo pipefail
BUILD=${1:-build-gpu}
TARBALL=${2:-.gpu-bundle/clothbench-gpu.tar.xz}
JOBS=${JOBS:-2}
COMMIT=$(git rev-parse "${COMMIT:-HEAD}")
rm -rf "$BUILD/src" && mkdir -p "$BUILD/src"
git archive "$COMMIT" | tar -x -C "$BUILD/src"
# OSMesa (is-gl, OpenGL pictures) pulls in a 117 MB libLLVM, OpenVDB 57 MB and FCL is not needed here:
# off. Embree (the accuracy oracle of `clothbench run`) and EGL (is-egl) stay.
cmake -S "$BUILD/src" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCLOTHBENCH_WITH_GL=OFF -DCLOTHBENCH_WITH_VDB=OFF \
  -DCLOTHBENCH_WITH_FCL=OFF -DCLOTHBENCH_WITH_EGL=ON -DCLOTHBENCH_WITH_EMBREE=ON -DCLOTHBENCH_BUILD_PERF=OFF \
  -DCLOTHBENCH_BUILD_TESTS=ON -DCLOTHBENCH_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$BUILD" -j"$JOBS" --target clothbench collide_is_bench collide_is_tests

stage="$BUILD/bundle/clothbench-gpu"
rm -rf "$stage" && mkdir -p "$stage/bin" "$stage/lib/cxx"
cp "$BUILD/bin/clothbench" "$BUILD/bin/collide_is_bench" "$BUILD/tests/collide_is/collide_is_tests" "$stage/bin/"
# every library ldd resolves, glibc's own (libc, libm, ld-linux, ...) excepted; TBB's malloc is dlopened
libs=$(ldd "$stage"/bin/* | awk '/=> \//{print $3}' | sort -u)
for lib in $libs /usr/lib/x86_64-linux-gnu/libtbbmalloc.so.2; do
  name=$(basename "$lib")
  case "$name" in
    libc.so.*|libm.so.*|libdl.so.*|librt.so.*|libpthread.so.*|ld-linux*|libmvec.so.*) ;;
    libstdc++.so.*|libgcc_s.so.*) cp -L "$lib" "$stage/lib/cxx/$name" ;;
    *) cp -L "$lib" "$stage/lib/$name" ;;
  esac
done
# the GL call timer (gl_timer.c), LD_PRELOADed by run-on-gpu.sh's instrumented runs only
mkdir -p "$stage/preload"
cc -O2 -Wall -Wextra -shared -fPIC -o "$stage/preload/libcb_gl_timer.so" tools/gpu-bundle/gl_timer.c -ldl
strip --strip-unneeded "$stage"/bin/* "$stage"/lib/*.so* "$stage"/lib/cxx/*.so* 2>/dev/null || true
{
  echo "git_commit: $COMMIT (git archive: committed files only)"
  # the programs look for scenes' garment files beside the scene, then under this folder (CLOTHBENCH_SOURCE_DIR):
  # run-on-gpu.sh links it to the repository where it is absent
  echo "source_dir: $(cd "$BUILD/src" && pwd)"
  echo "built: $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(. /etc/os-release; echo "$PRETTY_NAME"), $(g++ --version | head -1)"
  echo "cmake: $(grep -E '^CLOTHBENCH_WITH_[A-Z]+:BOOL' "$BUILD/CMakeCache.txt" | tr '\n' ' ')"
  echo "needs: glibc >= $(objdump -T "$stage"/bin/* "$stage"/lib/*.so* | grep -o 'GLIBC_2\.[0-9]*' | sort -V | tail -1 | cut -d_ -f2)," \
       "GLIBCXX $(objdump -T "$stage"/bin/* "$stage"/lib/*.so* | grep -o 'GLIBCXX_3\.4\.[0-9]*' | sort -V | tail -1 | cut -d_ -f2) (else lib/cxx)"
  echo "libraries (Debian packages):"
  for f in "$stage"/lib/*.so* "$stage"/lib/cxx/*.so*; do
    n=$(basename "$f")
    p=$({ dpkg -S "/usr/lib/x86_64-linux-gnu/$n" || dpkg -S "/lib/x86_64-linux-gnu/$n"; } 2>/dev/null | head -1 | cut -d: -f1-2 || true)
    echo "  $n ${p:+$p $(dpkg-query -W -f='${Version}' "$p")}"
  done
} > "$stage/BUILD-INFO"
mkdir -p "$(dirname "$TARBALL")"
tar -C "$(dirname "$stage")" -cJf "$TARBALL" clothbench-gpu
cat "$stage/BUILD-INFO"
ls -la "$TARBALL"
