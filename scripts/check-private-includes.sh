#!/bin/sh
# A folder under lib/ includes its own private headers, public headers
# (curvetext/...), and another folder's private header only when that
# header's first line names it an interface for other stages ("Private
# interface of <folder>/ ..."). Prints each include that breaks the rule;
# exits 1 if there is one.
cd "$(dirname "$0")/../lib" || exit 2
status=0
for file in $(find . -name '*.cpp' -o -name '*.hpp' | sed 's|^\./||'); do
  folder=${file%%/*}
  grep -o '^#include "[a-z_]*/[a-z_0-9]*\.hpp"' "$file" | sed 's/^#include "//; s/"$//' | while read -r header; do
    case "$header" in curvetext/* | "$folder"/*) continue ;; esac
    if ! head -n 1 "$header" | grep -q "^// Private interface of ${header%%/*}/ "; then
      echo "lib/$file includes $header, private to ${header%%/*}/"
      exit 1
    fi
  done || status=1
done
exit $status
