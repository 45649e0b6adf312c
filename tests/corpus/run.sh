#!/usr/bin/env bash
# Runs every corpus program as expected.tsv says (machine, options) and prints path, exit status
# and first error. Fails if a program crashes or is refused as bad usage (exit other than 0 or 1),
# or if a program listed in completes.txt does not complete.
# The programs are other people's and are not in this repository: they are read from
# ../shared/corpus beside the checkout (NCURVE_CORPUS overrides); without it the test is skipped
# (exit 77, ctest's SKIP_RETURN_CODE).
# usage: tests/corpus/run.sh [NCURVE]   (default build/ncurve)
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
ncurve="$(realpath "${1:-$here/../../build/ncurve}")"
corpus="${NCURVE_CORPUS:-$here/../../../shared/corpus}"
if [ ! -d "$corpus" ]; then
  echo "SKIP: the corpus of public programs is not at $corpus (the folder shared/ beside the checkout;" \
       "set NCURVE_CORPUS to where it is)" >&2
  exit 77
fi
corpus="$(cd "$corpus" && pwd)"
cd "$corpus"
failed=0
declare -A result
while IFS=$'\t' read -r path machine expected today opts; do
  [ "$path" = path ] && continue
  if [ ! -e "$path" ]; then
    echo "FAIL: $path is listed in expected.tsv but not in $corpus" >&2
    failed=1
    continue
  fi
  extra=()
  [ "$machine" = lathe ] && [[ "$opts" != *--machine* ]] && extra=(--machine fanuc-lathe)
  # the project's own profiles for these programs live beside this script
  opts="${opts//--machine profiles\//--machine $here/profiles/}"
  # shellcheck disable=SC2086
  out=$(timeout 60 "$ncurve" run "$path" "${extra[@]}" $opts --max-steps 2000000 2>&1)
  rc=$?
  first=$(printf '%s\n' "$out" | grep -m1 "error:" | sed 's/.*error: //' | cut -c1-80)
  printf '%s\t%s\t%s\n' "$path" "$rc" "$first"
  result[$path]=$rc
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 1 ]; then
    echo "FAIL: $path exited $rc" >&2
    failed=1
  fi
done < "$here/expected.tsv"
while read -r path; do
  [ -z "$path" ] && continue
  if [ "${result[$path]:-missing}" != 0 ]; then
    echo "FAIL: $path should complete (exit ${result[$path]:-missing})" >&2
    failed=1
  fi
done < "$here/completes.txt"
total=${#result[@]}
done_count=0
for k in "${!result[@]}"; do [ "${result[$k]}" = 0 ] && done_count=$((done_count + 1)); done
echo "$done_count of $total corpus programs complete"
exit $failed
