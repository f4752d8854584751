#!/usr/bin/env bash
# Formats every C++ file git tracks with Debian's clang-format-14 (named explicitly, so every machine
# formats alike; .clang-format at the top holds the style).
#   scripts/format.sh           rewrite the files in place
#   scripts/format.sh --check   change nothing; list the files that differ and exit 1 if there are any
set -euo pipefail
cd "$(dirname "$0")/.."

formatter=clang-format-14
if ! command -v "$formatter" >/dev/null; then
  echo "format: $formatter not found (scripts/setup.sh installs it)" >&2
  exit 2
fi
mode=fix
case "${1:-}" in
  "") ;;
  --check) mode=check ;;
  *) echo "usage: scripts/format.sh [--check]" >&2; exit 2 ;;
esac

mapfile -d '' files < <(git ls-files -z -- '*.cpp' '*.hpp' '*.h' '*.cc' '*.inl')
if [ "$mode" = fix ]; then
  [ ${#files[@]} -eq 0 ] || printf '%s\0' "${files[@]}" | xargs -0 -n 50 "$formatter" -i --style=file
  exit 0
fi

# One clang-format process per batch of files: --dry-run names each file that would change.
differ=()
if [ ${#files[@]} -ne 0 ]; then
  mapfile -t differ < <(printf '%s\0' "${files[@]}" |
    xargs -0 -n 100 "$formatter" --style=file --dry-run --ferror-limit=1 2>&1 |
    sed -n 's/^\(.*\):[0-9]*:[0-9]*: \(warning\|error\): code should be clang-formatted.*/\1/p' | sort -u)
fi
if [ ${#differ[@]} -ne 0 ]; then
  echo "format: ${#differ[@]} file(s) differ from $formatter's formatting (run scripts/format.sh):" >&2
  printf '  %s\n' "${differ[@]}" >&2
  exit 1
fi
echo "format: ${#files[@]} files formatted alike"
