# slipwave-law rejects bad jump-history files with one error line that names the file line:
# missing column, non-numeric value, unsorted time, wrong number of values, missing file.
set -u
BUILD=${BUILD:-build}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
opts="-interface_E 1e8 -interface_G 5e7"
fail=0
expect() { # file, regex
  out=$("$BUILD/slipwave-law" -path "$1" $opts 2>&1 >/dev/null); rc=$?
  if [ $rc -eq 0 ] || ! grep -Eq "$2" <<<"$out" || [ "$(wc -l <<<"$out")" -ne 1 ]; then
    echo "FAIL: $1 (exit $rc): expected one line matching /$2/, got:"; echo "$out"; fail=1
  else
    echo "ok: $out"
  fi
}
printf 't,w_T\n1,0.1\n' > "$tmp/missing.csv"
expect "$tmp/missing.csv" "^slipwave-law: error: .*missing.csv:1: missing column w_N"
printf 't,w_T,w_N\n1,0,0\n2,1e-4,0\n3,abc,0\n' > "$tmp/nonnum.csv"
expect "$tmp/nonnum.csv" "nonnum.csv:4: column w_T: 'abc' is not a finite number"
printf 't,w_T1,w_T2,w_N\n# comment\n1,0,0,0\n2,0,0,0\n1.5,0,0,0\n' > "$tmp/unsorted.csv"
expect "$tmp/unsorted.csv" "unsorted.csv:5: time 1.5 does not increase"
printf 't,w_T,w_N\n1,0\n' > "$tmp/short.csv"
expect "$tmp/short.csv" "short.csv:2: 2 values, expected 3"
printf 't,w_T,w_X\n' > "$tmp/unknown.csv"
expect "$tmp/unknown.csv" "unknown.csv:1: missing column w_N"
printf 't,w_T,w_N\n' > "$tmp/empty.csv"
expect "$tmp/empty.csv" "empty.csv:1: no data rows"
expect "$tmp/none.csv" "none.csv: cannot open the file"
exit $fail
