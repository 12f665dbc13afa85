#!/usr/bin/env bash
# Seeds the fuzz corpus from the shared SLR files: usage make_seeds.sh SHARED_SLR_DIR CORPUS_DIR.
# Copies every file whole, adds the first 150 lines of each (small inputs mutate faster), a
# CRD pass + "====" + CPF excerpt (exercises the O-C), and a small O-C CSV. Writes only into
# CORPUS_DIR (under the build tree), never into the source tree.
set -euo pipefail
src=${1:?shared slr folder}; out=${2:?corpus folder}
mkdir -p "$out"
if [ ! -d "$src" ]; then
  echo "make_seeds: $src not found; starting from a minimal corpus" >&2
else
  for f in "$src"/*; do
    [ -f "$f" ] || continue
    b=$(basename "$f")
    cp "$f" "$out/seed-$b"
    head -n 150 "$f" > "$out/seed-head-$b"
  done
  if [ -f "$src/blits_201206.frd" ] && [ -f "$src/blits_cpf_120626_6801.hts" ]; then
    # The MATM pass of 2012-06-27 08:49 and the CPF records around it (lines 470-540).
    awk 'tolower($1)=="h1"{buf=""; keep=0} {buf=buf $0 "\n"} tolower($1)=="h4" && $5==27 && $6==8 && $7==49 {keep=1}
         tolower($1)=="h8"{ if(keep) printf "%s", buf; keep=0 }' "$src/blits_201206.frd" > "$out/seed-matm-pass.tmp"
    { cat "$out/seed-matm-pass.tmp"; echo "===="; sed -n '1,3p;470,540p' "$src/blits_cpf_120626_6801.hts"; } > "$out/seed-oc-matm"
    rm -f "$out/seed-matm-pass.tmp"
  fi
fi
printf 'epoch_s,oc_s,elevation_deg\n31787.7,1.5e-9,22.7\n31788.2,-2e-10,22.8\n# comment\n"31788.7","3e-10",""\n' > "$out/seed-oc.csv"
ls "$out" | wc -l | xargs echo "make_seeds: corpus files:"
