#!/usr/bin/env bash
# Fails (exit 1) when a tracked C++ source is not laid out as .clang-format says, naming each.
# Fix with: git ls-files '*.cpp' '*.h' | xargs clang-format -i
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
format="$(command -v clang-format || command -v clang-format-14 || true)"
if [ -z "$format" ]; then
  echo "check_format: clang-format is not installed (dev.sh installs it)" >&2
  exit 1
fi
bad=()
while IFS= read -r file; do
  if ! "$format" --dry-run --Werror "$file" >/dev/null 2>&1; then bad+=("$file"); fi
done < <(git ls-files '*.cpp' '*.h' '*.hpp')
if [ "${#bad[@]}" -gt 0 ]; then
  printf '%s: not clang-format clean\n' "${bad[@]}" >&2
  echo "check_format: ${#bad[@]} file(s) to format (clang-format -i FILE)" >&2
  exit 1
fi
echo "check_format: every tracked C++ file is clang-format clean"
