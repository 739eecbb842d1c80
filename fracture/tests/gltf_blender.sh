#!/usr/bin/env bash
# fracture --gltf imported by Blender headless (gltf_blender.py); exit 77 without blender.
set -u
dtlab=$1
command -v blender >/dev/null || { echo "SKIP: blender is not installed"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$dtlab" fracture builtin --pieces 6 --seed 1 --quiet --gltf --out "$tmp/f" >/dev/null || { echo "FAIL: fracture"; exit 1; }
blender -b --factory-startup --python-exit-code 1 -P "$(dirname "$0")/gltf_blender.py" -- "$tmp/f" 2>&1 |
  grep -E "^(blender:|FAIL|Error)"
exit "${PIPESTATUS[0]}"
