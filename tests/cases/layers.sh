#!/usr/bin/env bash
# Includes point down the layers: a file may include headers of its own layer and of the
# layers below it, never of a layer above. The order, lowest first (docs/architecture.md
# draws it):
#   0 core       log events and stages, user-input errors, the unused-option check
#   1 physics    pure kernels: materials, interface law, damping, stable step (no PETSc)
#   2 fem mesh time   discretisation: element kernels and bulk operator, DMPlex building,
#                labelling and interface splitting, the central-difference TS. fem and mesh
#                share the layer: the splitter integrates face weights with the element
#                kernels and the bulk operator reads the region label (mesh/labels.hpp)
#   3 interface  the split-node interface: options and assembler
#   4 model      the assembled problem: materials, boundary conditions, free field,
#                attenuation, input motion, energy ledger, geostatic stage
#   5 io         writers and readers: fields, stations, interface output, jump histories
#   6 app        the driver: SimulationRun, checkpoint
#   7 bin        the programs (src/bin)
# Every directory of include/slipwave/ and src/ must be in the table, so a new one gets a
# place before it is used. Fails naming each upward include (file:line, both layers).
set -u
cd "$(dirname "$0")/../.."

layer_rank() {
  case "$1" in
    core) echo 0 ;;
    physics) echo 1 ;;
    fem | mesh | time) echo 2 ;;
    interface) echo 3 ;;
    model) echo 4 ;;
    io) echo 5 ;;
    app) echo 6 ;;
    bin) echo 7 ;;
    *) echo -1 ;;
  esac
}

# check_tree ROOT: prints one line per upward include or unplaced directory; exit 1 if any.
check_tree() {
  local root=$1 bad=0 f dir rank line target tdir trank
  while IFS= read -r f; do
    dir=${f#"$root"/}; dir=${dir#include/slipwave/}; dir=${dir#src/}; dir=${dir%%/*}
    rank=$(layer_rank "$dir")
    if [ "$rank" -lt 0 ]; then echo "${f#"$root"/}: directory '$dir' has no layer (add it to tests/cases/layers.sh)"; bad=1; continue; fi
    while IFS= read -r line; do
      target=${line#*:}; target=${target#*\"slipwave/}; tdir=${target%%/*}
      trank=$(layer_rank "$tdir")
      if [ "$trank" -lt 0 ]; then
        echo "${f#"$root"/}:${line%%:*}: includes slipwave/$tdir/, which has no layer"; bad=1
      elif [ "$trank" -gt "$rank" ]; then
        echo "${f#"$root"/}:${line%%:*}: $dir (layer $rank) includes slipwave/${target%%\"*} ($tdir, layer $trank)"; bad=1
      fi
    done < <(grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"slipwave/' "$f")
  done < <(find "$root/include/slipwave" "$root/src" -type f \( -name '*.hpp' -o -name '*.cpp' \) | sort)
  return "$bad"
}

# The check must be able to fail: a tree with one upward include (physics -> model) and one
# sideways include (fem -> mesh, allowed) must give exactly one violation.
fake=$(mktemp -d); trap 'rm -rf "$fake"' EXIT
mkdir -p "$fake/include/slipwave/physics" "$fake/src/fem"
printf '#include "slipwave/model/materials.hpp"\n' >"$fake/include/slipwave/physics/up.hpp"
printf '#include "slipwave/mesh/labels.hpp"\n#include "slipwave/physics/up.hpp"\n' >"$fake/src/fem/side.cpp"
if out=$(check_tree "$fake") || [ "$(grep -c . <<<"$out")" -ne 1 ]; then
  echo "self-test: expected exactly one violation in the fake tree, got:"; echo "$out"; exit 1
fi

if ! out=$(check_tree .); then
  echo "includes pointing up the layers:"; echo "$out"; exit 1
fi
echo "all $(find include/slipwave src -type f \( -name '*.hpp' -o -name '*.cpp' \) | wc -l) files include only their own layer or the layers below"
