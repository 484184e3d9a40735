#!/usr/bin/env bash
# crossdiv's two entry points for a Debian 12 machine (run as root on a fresh machine):
#   ./run.sh main   install what is missing, build, run the benchmark and the default conformance
#                   suite, and write out/{results.json,results.csv,junit.xml,bench.json,report.md,index.html}
#   ./run.sh test   install what is missing, build, run every test with CTest
# and, for reliability (fuzz/README.md):
#   ./run.sh sanitize [SECONDS]   build with clang, AddressSanitizer and UndefinedBehaviorSanitizer
#                   into build-sanitize, run every test there, then each libFuzzer target for
#                   SECONDS (default 30)
#   ./run.sh corpus [I/N]   install the real-mesh corpora (Debian data packages), build, and run
#                   the corpus suite over them into out/corpus, stating its time; with I/N, its
#                   shard I of N only, into out/corpus-shards/I (on N machines, or one after
#                   another), joined by `crossdiv merge out/corpus-shards/* --out out/corpus`
set -euo pipefail
cd "$(dirname "$0")"
# The project's Python is Debian's /usr/bin/python3, the one its packages (numpy, Open3D, Dask,
# pytest) install into; every test that starts `python3` (subjects, adapters, examples) starts
# that one. A python3 earlier on PATH, such as a pyenv shim (measured on the CI machine: 1 s per
# start against 0.09 s, and no numpy), would make each start slower and miss the packages.
export PATH="/usr/bin:$PATH"

# The time of every phase: with CROSSDIV_PHASE_LOG set (.ci/run sets it), each phase appends
# "SECONDS STATUS NAME" to that file when it ends, ok or failed, so a slow phase is visible in
# every CI log.
phase_name=""
phase_start=0
end_phase() {
  if [ -n "$phase_name" ] && [ -n "${CROSSDIV_PHASE_LOG:-}" ]; then
    echo "$((SECONDS - phase_start)) $1 $phase_name" >> "$CROSSDIV_PHASE_LOG"
  fi
  phase_name=""
}
begin_phase() {
  end_phase ok
  phase_name="$1"
  phase_start=$SECONDS
}
trap 'if [ $? -eq 0 ]; then end_phase ok; else end_phase failed; fi' EXIT

# Debian packages the build, the references and the tests need (meshlab, xvfb and xauth: the
# external MeshLab reference of the default suite, run as meshlabserver under Xvfb; python3-open3d:
# the Open3D reference, adapters/open3d; blender: Blender's Subdivision Surface modifier, run headless,
# adapters/blender; python3-skimage: scikit-image's marching cubes, the
# isosurface reference; help2man and man-db: the man page, generated from the binary's help and
# rendered by its test; opensubdiv-tools: the programs OpenSubdiv's regression shapes are
# compiled into, datasets/install_opensubdiv_shapes.py; mkdocs, mkdocs-material and doxygen:
# the documentation site and its C++ API reference, built in strict mode by their test;
# python3-distributed: Dask, for crossdiv-cluster and its LocalCluster test; assimp-testmodels: the
# corpus of real meshes, optional data read in place, never committed: a fixed sample in the main
# job, all of it in ./run.sh corpus).
PACKAGES="g++ make cmake ccache libeigen3-dev libosd-dev libopenmesh-dev libcgal-dev libvtk9-dev libgtest-dev \
libcli11-dev nlohmann-json3-dev libfmt-dev libnanoflann-dev libassimp-dev python3-matplotlib python3-numpy \
meshlab xvfb xauth python3-open3d blender \
python3-pytest python3-skimage \
libjs-three chromium chromium-driver python3-selenium python3-pil \
pybind11-dev python3-dev python3-scipy help2man man-db opensubdiv-tools mkdocs mkdocs-material doxygen python3-distributed assimp-testmodels"

install_missing() {
  local missing=""
  for p in $PACKAGES; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
  done
  if [ -n "$missing" ]; then
    if [ "$(id -u)" -ne 0 ]; then
      echo "missing Debian packages:$missing (run as root, or: sudo apt-get install$missing)" >&2
      exit 2
    fi
    # apt's and dpkg's lines (hundreds on a fresh machine) go to a log, shown when they fail.
    local log=/var/log/crossdiv-apt.log
    echo "installing:$missing (log: $log)"
    if ! { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing; } > "$log" 2>&1; then
      tail -n 40 "$log" >&2
      echo "apt-get could not install:$missing" >&2
      exit 2
    fi
  fi
  # Real meshes from Debian's libcgal-demo, unpacked into datasets/cgal (optional data).
  [ -d datasets/cgal ] || datasets/install_cgal_meshes.sh || echo "CGAL demo meshes unavailable; continuing without them"
  # OpenSubdiv's regression shapes with hierarchical edits, out of Debian's opensubdiv-tools
  # (optional data: Hbr gives them their verdict).
  [ -d datasets/opensubdiv ] || /usr/bin/python3 datasets/install_opensubdiv_shapes.py || echo "OpenSubdiv shapes unavailable; continuing without them"
}

# The corpora ./run.sh corpus adds (verification/suites/corpus.suite): Sweet Home 3D's furniture.
CORPUS_PACKAGES="sweethome3d-furniture"

# The sanitizer build: clang (and its sanitizer and libFuzzer runtimes).
SANITIZE_PACKAGES="clang libclang-rt-14-dev"

# CTest, with the whole output in DIR/ctest.log and on the screen only what says something: a
# failing test's result with its output, and the summary. Hundreds of lines of passes would push a
# failure out of a capped CI log.
run_ctest() {
  local dir="$1"
  echo "ctest --test-dir $dir (the whole output: $dir/ctest.log)"
  ctest --test-dir "$dir" --output-on-failure -j2 2>&1 | tee "$dir/ctest.log" |
    grep -v -E '^ +Start +[0-9]+: |Passed +[0-9.]+ sec$'
}

# Compiler cache: every compilation goes through ccache (Debian's), in its default folder
# (~/.cache/ccache), so a build of sources this machine has compiled before, in any clone, takes
# seconds instead of minutes. Paths under the source tree are hashed relative to it (base_dir) and
# the working folder is not hashed (hash_dir), so two clones in different folders share entries;
# a cold cache (a new machine) builds as without it. CI prints the cache's hit count.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=true

# CROSSDIV_WERROR=ON (CI) turns every compiler warning into an error.
configure() {
  local launcher=()
  if command -v ccache > /dev/null; then
    launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
  cmake "$@" "${launcher[@]}" -DCMAKE_COMPILE_WARNING_AS_ERROR="${CROSSDIV_WERROR:-OFF}"
}

build() {
  begin_phase configure
  configure -S . -B build -DCMAKE_BUILD_TYPE=Release
  begin_phase "release build"
  cmake --build build -j2   # 2 jobs: CGAL translation units need ~1 GB each
}

case "${1:-}" in
  main)
    begin_phase apt
    install_missing
    build
    # The benchmark first, so that the suite's report includes its timing section.
    begin_phase bench
    ./build/verification/crossdiv bench --out out
    begin_phase suite
    ./build/verification/crossdiv suite --out out
    # The report as a reader opens it: headless Chromium, screenshots in out/screenshots.
    begin_phase "browser check"
    /usr/bin/python3 reports/check_viewer.py out --screenshots
    ;;
  test)
    begin_phase apt
    install_missing
    build
    begin_phase "release tests"
    run_ctest build
    ;;
  sanitize)
    PACKAGES="$PACKAGES $SANITIZE_PACKAGES"
    begin_phase apt
    install_missing
    # -O1: usable stacks at a bearable speed; -gline-tables-only: file and line in every
    # sanitizer report, without the full debug information that costs compile and link time;
    # NDEBUG as in the release build, so the reference libraries take the same code paths
    # (CGAL's assertions among them).
    begin_phase configure
    CC=clang CXX=clang++ configure -S . -B build-sanitize -DCROSSDIV_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG"
    begin_phase "sanitizer build"
    cmake --build build-sanitize -j2
    # handle_segv=0: a deliberate crash (the isolation tests) dies by its signal, as the
    # harness expects; any sanitizer report fails the test that caused it.
    # max_allocation_size_mb: the isolation's memory cap (kIsolatedMemoryBytes, an address-space
    # limit the sanitizer's shadow memory rules out) as a cap per allocation, so a reference
    # that allocates without bound stops at its first 6 GiB request.
    export ASAN_OPTIONS=handle_segv=0:detect_leaks=1:abort_on_error=0:max_allocation_size_mb=6144
    export LSAN_OPTIONS="suppressions=$PWD/fuzz/sanitizer-suppressions.txt"
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    begin_phase "sanitizer tests"
    run_ctest build-sanitize
    # Two targets at a time: one per core of the 2-core machines this runs on.
    begin_phase fuzzers
    CROSSDIV_FUZZ_PARALLEL=2 fuzz/run_fuzzers.sh build-sanitize "${2:-30}"
    ;;
  corpus)
    PACKAGES="$PACKAGES $CORPUS_PACKAGES"
    begin_phase apt
    install_missing
    # Sweet Home 3D's furniture models, out of their zip catalogs into datasets/corpus (optional data).
    [ -d datasets/corpus/sweethome3d ] || /usr/bin/python3 datasets/install_sweethome3d_corpus.py
    build
    begin_phase corpus
    corpus_start=$SECONDS
    # Its time is stated whether or not a case failed; the exit status is the suite's.
    corpus_status=0
    if [ -n "${2:-}" ]; then
      shard_out="out/corpus-shards/${2%%/*}"
      ./build/verification/crossdiv suite verification/suites/corpus.suite --shard "$2" --out "$shard_out" || corpus_status=$?
      echo "corpus suite, shard $2: $((SECONDS - corpus_start)) s (results and report in $shard_out;" \
           "with every shard in: ./build/verification/crossdiv merge out/corpus-shards/* --out out/corpus)"
    else
      ./build/verification/crossdiv suite verification/suites/corpus.suite --out out/corpus || corpus_status=$?
      echo "corpus suite: $((SECONDS - corpus_start)) s (results and report in out/corpus)"
    fi
    exit "$corpus_status"
    ;;
  *)
    echo "usage: $0 main|test|sanitize [SECONDS]|corpus [I/N]" >&2
    exit 2
    ;;
esac
