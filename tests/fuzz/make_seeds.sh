#!/usr/bin/env bash
# Seeds the fuzz corpora: usage make_seeds.sh SHARED_SLR_DIR SEEDS_DIR FUZZ_SEEDS_EXE
# Writes SEEDS_DIR/<target>/ (under the build tree, never the source tree), replacing what a
# previous run wrote there:
# - fuzz_seeds (tests/fuzz/fuzz_seeds.cpp): files from the project's simulators and writers and
#   the header/value variants the tests use, for the CSV, JSON, image and session targets;
# - from the shared ILRS files (not copied whole: cut to fit the fuzzers' -max_len, 4 KiB):
#   crd:    each CRD file's first two passes, their headers and up to 8 records of each data
#           type, then H9; and each file's first 4 KiB as it is (crd_check gets the same);
#   cpf:    the header and 12 position records of each CPF, then 99;
#   sinex:  the header line, every block with its column-title comment and first 6 data lines
#           (the FILE/COMMENT, FILE/REFERENCE and INPUT/HISTORY blocks empty), then %ENDSNX;
#   slr_oc: the BLITS MATM pass of 2012-06-27 08:49 (20 ranges), "====", and the CPF records
#           around it (enough for the Lagrange interpolation);
# - csv gets every CSV seed, json every JSON seed.
set -euo pipefail
src=${1:?shared slr folder}; out=${2:?seeds folder}; gen=${3:?fuzz_seeds executable}
rm -rf "$out"
mkdir -p "$out"/{crd,cpf,sinex,slr_oc,csv,json}
"$gen" "$out"

crd_cut() {  # headers, up to 8 records of each data type per pass, first two passes, H9
  awk '{t=tolower($1)}
       t=="h4"{pass++; delete n}
       pass>2 && t!="h9"{next}
       t ~ /^h/ || t ~ /^c/ || t=="00" {print; next}
       n[t]++ < 8 {print}' "$1"
  grep -qi '^h9' "$1" || echo "H9"
}

if [ ! -d "$src" ]; then
  echo "make_seeds: $src not found; the SLR corpora start from the generated seeds only" >&2
else
  shopt -s nullglob nocaseglob
  for f in "$src"/*.{frd,npt,crd,fr2,np2}; do
    b=$(basename "$f")
    crd_cut "$f" > "$out/crd/seed-cut-$b"
    head -c 4096 "$f" > "$out/crd/seed-head-$b"
  done
  for f in "$src"/*.{hts,cpf}; do
    b=$(basename "$f")
    awk 'tolower($1) ~ /^h/ {print; next} $1=="10" && n++ < 12 {print} END {print "99"}' "$f" > "$out/cpf/seed-$b"
  done
  for f in "$src"/*.snx; do
    b=$(basename "$f")
    awk '/^%=/ || /^%ENDSNX/ {print; next}
         /^\+/ {block=$1; print; n=0; next}
         /^-/ {print; next}
         block=="+FILE/COMMENT" || block=="+FILE/REFERENCE" || block=="+INPUT/HISTORY" {next}
         /^\*/ {if (n == 0) print; next}
         n++ < 6 {print}' "$f" > "$out/sinex/seed-$b"
  done
  shopt -u nocaseglob
  frd="$src/blits_201206.frd"; cpf="$src/blits_cpf_120626_6801.hts"
  if [ -f "$frd" ] && [ -f "$cpf" ]; then
    # The MATM pass of 2012-06-27 08:49 (ranges 31787-32139 s of MJD 56105) and the CPF records
    # from 30000 to 33840 s of that day (lines 495-511 of the file), with the CPF header.
    awk 'tolower($1)=="h1"{buf=""; keep=0; n=0; m=0} tolower($1)=="h4" && $5==27 && $6==8 && $7==49 {keep=1}
         { t=tolower($1) }
         t=="10" && n++ >= 20 {next}
         t=="20" && m++ >= 2 {next}
         t=="30" || t=="40" {next}
         {buf=buf $0 "\n"}
         t=="h8"{ if(keep) printf "%s", buf; keep=0 }' "$frd" > "$out/slr_oc/seed-matm"
    { echo "===="; sed -n '1,3p;495,511p' "$cpf"; echo "99"; } >> "$out/slr_oc/seed-matm"
  fi
fi
mkdir -p "$out/crd_check" && cp "$out"/crd/* "$out/crd_check/" 2>/dev/null || true  # (the checker reads what the reader does)
for d in "$out"/*_csv "$out"/oc_csv; do cp "$d"/* "$out/csv/" 2>/dev/null || true; done
for d in "$out"/footprint_config "$out"/slr_config "$out"/calib_config "$out"/radiometry_config "$out"/trend_config "$out"/slr_presets "$out"/beams_json "$out"/session; do
  cp "$d"/* "$out/json/" 2>/dev/null || true
done
for d in "$out"/*/; do echo "make_seeds: $(basename "$d"): $(ls "$d" | wc -l) seeds"; done
