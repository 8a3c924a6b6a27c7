#!/usr/bin/env bash
# docs/presets.md must hold, between its "<!-- grass presets -->" and "<!-- /grass presets -->"
# lines, exactly what `grass presets` prints: the documented presets are the built-in ones.
#
#   presets_doc_test.sh GRASS_BIN DOC
set -u
bin=$1
doc=$2
expected=$("$bin" presets) || { echo "grass presets failed" >&2; exit 1; }
documented=$(sed -n '/^<!-- grass presets -->$/,/^<!-- \/grass presets -->$/p' "$doc" | sed '1d;$d')
if [ -z "$documented" ]; then
    echo "$doc: no block between <!-- grass presets --> and <!-- /grass presets -->" >&2
    exit 1
fi
if [ "$expected" != "$documented" ]; then
    echo "$doc: the presets table differs from 'grass presets'; paste its output in:" >&2
    diff <(echo "$documented") <(echo "$expected") >&2
    exit 1
fi
echo "docs/presets.md matches grass presets"
