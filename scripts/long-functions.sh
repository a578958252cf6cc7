#!/bin/sh
# long-functions.sh - the functions of src/ longer than LIMIT lines
# (default 120), longest first: "LINES FILE:LINE NAME".  A function is
# counted from its opening brace at column 0 to its closing one (kernel
# style, as every file of src/ is written).  Exits 1 if there is any.
#   sh scripts/long-functions.sh [LIMIT]
cd "$(dirname "$0")/.." || exit 2
limit=${1:-120}
find src -name '*.c' | sort | xargs awk -v limit="$limit" '
FNR == 1 { prev = "" }
/^\{/ { start = FNR; name = prev; sub(/\(.*/, "", name); n = split(name, w, /[ *]+/); name = w[n] }
/^\}/ && start { len = FNR - start - 1; if (len > limit) printf "%d %s:%d %s\n", len, FILENAME, start, name; start = 0 }
{ if ($0 ~ /^[a-z].*\(/) prev = $0 }
' | sort -rn | tee /tmp/long-functions.$$ 
test ! -s /tmp/long-functions.$$; rc=$?; rm -f /tmp/long-functions.$$; exit $rc
