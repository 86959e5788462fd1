# slipwave-law rejects bad parameters with one line naming the option, its value and the
# allowed range; also `auto` stiffness (no mesh here), misspelled options, missing -path.
set -u
BUILD=${BUILD:-build}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
printf 't,w_T,w_N\n1,1e-4,0\n' > "$tmp/in.csv"
fail=0
expect() { # regex, options...
  local re=$1; shift
  out=$("$BUILD/slipwave-law" -path "$tmp/in.csv" "$@" 2>&1 >/dev/null); rc=$?
  if [ $rc -eq 0 ] || ! grep -Eq -- "$re" <<<"$out" || [ "$(wc -l <<<"$out")" -ne 1 ]; then
    echo "FAIL: $* (exit $rc): expected one line matching /$re/, got:"; echo "$out"; fail=1
  else
    echo "ok: $out"
  fi
}
k="-interface_E 1e8 -interface_G 5e7"
expect "^slipwave-law: error: -interface_psi = 35 deg; allowed 0 <= psi <= phi = 30 deg" $k -interface_phi 30 -interface_psi 35
expect "-interface_E = -1 Pa/m; allowed E > 0" -interface_E -1 -interface_G 5e7
expect "-interface_G = 0 Pa/m; allowed G > 0" -interface_E 1e8 -interface_G 0
expect "-interface_phi = 90 deg; allowed 0 <= phi < 90" $k -interface_phi 90
expect "-interface_c = -1 Pa; allowed c >= 0" $k -interface_c -1
expect "-interface_e_ini = -0.001 m; allowed e_ini >= 0" $k -interface_e_ini -1e-3
expect "-interface_tensile_strength = 5000 Pa; allowed 0 <= tensile_strength <= c / tan\(phi\) = 3464.1" $k \
  -interface_c 2e3 -interface_phi 30 -interface_tensile_strength 5e3
expect "-interface_sigma_N0 = 10 Pa; allowed sigma_N0 <= tensile_strength = 0 Pa" $k -interface_sigma_N0 10
expect "-interface_E = auto needs a mesh" -interface_G 5e7
expect "-interface_G = auto needs a mesh" -interface_E 1e8 -interface_G auto
expect "-interface_E = stiff is not a number; allowed a stiffness > 0 \[Pa/m\] or auto" -interface_E stiff -interface_G 5e7
expect "unknown or unused option\(s\): -interface_phii 20" $k -interface_phii 20
out=$("$BUILD/slipwave-law" $k 2>&1); rc=$?
if [ $rc -eq 0 ] || ! grep -q -- "-path is required" <<<"$out"; then echo "FAIL: missing -path: $out"; fail=1; fi
# -help documents the options with their units.
help=$("$BUILD/slipwave-law" -help 2>&1)
for o in "-interface_E <[^>]*auto[^>]*>: Normal penalty stiffness \[Pa/m\]" "-interface_phi <30" "-interface_psi" "-interface_c" \
         "-interface_e_ini" "-interface_tensile_strength" "-interface_sigma_N0" "-path" "-output"; do
  grep -Eq -- "$o" <<<"$help" || { echo "FAIL: -help lacks $o"; fail=1; }
done
exit $fail
