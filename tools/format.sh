#!/bin/sh
# Formats every tracked C++ file with the tree's .clang-format (Debian 12's clang-format 14).
# With --check, changes nothing and exits non-zero when a file would change.
set -eu
cd "$(dirname "$0")/.."
files=$(git ls-files '*.h' '*.cpp')
if [ "${1:-}" = "--check" ]; then
  # shellcheck disable=SC2086
  clang-format --dry-run --Werror $files
else
  # shellcheck disable=SC2086
  clang-format -i $files
fi
