#!/usr/bin/env bash
# Fuzzes the file readers with libFuzzer under AddressSanitizer and UBSan: builds the targets of
# tests/fuzz with clang into build-fuzz/ (the library instrumented for coverage), writes their
# seeds and runs each target for SECONDS (default 300) on one core.
#   scripts/fuzz.sh [READER] [SECONDS]   READER: obj off ply stl scalar_file volume_cache vtk_xml
#                                        vtk_legacy pvd camera_json view_file evaluation_json
#                                        mesh_file font png exr, or all (default);
#                                        findings are written to
#                                        build-fuzz/findings/<reader>/
#   IVIS_FUZZ_JOBS=2 scripts/fuzz.sh ...  builds with 2 jobs (default 1)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
ivis_install_packages "${IVIS_FUZZ_PACKAGES[@]}"

READERS=(obj off ply stl scalar_file volume_cache vtk_xml vtk_legacy pvd camera_json view_file evaluation_json
  mesh_file font png exr)
CHOSEN=${1:-all}
if [[ "$CHOSEN" =~ ^[0-9]+$ ]]; then  # scripts/fuzz.sh SECONDS: every reader
  set -- all "$CHOSEN"
  CHOSEN=all
fi
SECONDS_PER_TARGET=${2:-300}
if [ "$CHOSEN" = all ]; then
  TARGETS=("${READERS[@]}")
elif [[ " ${READERS[*]} " == *" $CHOSEN "* ]]; then
  TARGETS=("$CHOSEN")
else
  echo "fuzz.sh: unknown reader '$CHOSEN' (known: ${READERS[*]}, all)" >&2
  exit 2
fi

FUZZ_BUILD=${IVIS_FUZZ_BUILD:-$IVIS_ROOT/build-fuzz}
# No alignment check: oneTBB's concurrent_hash_map (OpenVDB's trees register their accessors in one)
# casts tagged pointers such as 0x3 to nodes, which UBSan reports as a misaligned downcast.
FLAGS="-fsanitize=address,undefined -fno-sanitize=alignment -fno-sanitize-recover=undefined -fsanitize=fuzzer-no-link \
-fno-omit-frame-pointer"
CC=clang CXX=clang++ cmake -S "$IVIS_ROOT" -B "$FUZZ_BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DIVIS_BUILD_APP=OFF -DIVIS_BUILD_TESTS=OFF -DIVIS_BUILD_BENCH=OFF -DCMAKE_CXX_FLAGS="$FLAGS" >/dev/null
cmake --build "$FUZZ_BUILD" -j "${IVIS_FUZZ_JOBS:-1}" --target vtk_fuzz_seeds reader_fuzz_seeds "${TARGETS[@]/%/_fuzzer}"
"$FUZZ_BUILD/tests/fuzz/vtk_fuzz_seeds" "$FUZZ_BUILD/corpus"
"$FUZZ_BUILD/tests/fuzz/reader_fuzz_seeds" "$FUZZ_BUILD/corpus"
# font's seed: the font every picture uses (scripts/setup.sh installs it).
mkdir -p "$FUZZ_BUILD/corpus/font"
cp /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf "$FUZZ_BUILD/corpus/font/"
# mesh_file's seeds: every mesh seed behind the byte that names its format (mesh_file_fuzzer.cpp),
# once for each choice of what is shown.
mkdir -p "$FUZZ_BUILD/corpus/mesh_file"
for seed in "$FUZZ_BUILD"/corpus/{ply,obj,off,stl,vtk_legacy,vtk_xml}/*; do
  case "$seed" in
    *.ply) format=0 ;; *.obj) format=1 ;; *.off) format=2 ;; *.stl) format=3 ;; *.vtk) format=4 ;;
    *.vtp) format=5 ;; *.vtu) format=6 ;; *) continue ;;
  esac
  for shown in 0 1 2 3; do
    { printf "\\$(printf '%03o' $((format + 7 * shown)))"; cat "$seed"; } \
      >"$FUZZ_BUILD/corpus/mesh_file/$shown-$(basename "$seed")"
  done
done

status=0
for target in "${TARGETS[@]}"; do
  mkdir -p "$FUZZ_BUILD/findings/$target"
  echo "fuzz.sh: $target for $SECONDS_PER_TARGET s" >&2
  log="$FUZZ_BUILD/findings/$target.log"
  if "$FUZZ_BUILD/tests/fuzz/${target}_fuzzer" "$FUZZ_BUILD/corpus/$target" \
      -max_total_time="$SECONDS_PER_TARGET" -rss_limit_mb=2048 -malloc_limit_mb=1024 -timeout=10 \
      -artifact_prefix="$FUZZ_BUILD/findings/$target/" -print_final_stats=1 >"$log" 2>&1; then
    grep -E '^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)' "$log"
  else
    status=1
    echo "fuzz.sh: $target found a problem: $log and $FUZZ_BUILD/findings/$target/" >&2
    grep -E 'ERROR|SUMMARY|what\(\)' "$log" | head -n 5 >&2
  fi
done
exit $status
