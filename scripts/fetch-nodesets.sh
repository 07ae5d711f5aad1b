#!/usr/bin/env bash
# The OPC Foundation's NodeSet2 files (DI, IA, Machinery, ISA-95 job control, Machinery Jobs,
# Woodworking) for the OPC UA server, from the npm package node-opcua-nodesets at a pinned
# version (MIT; not kept in the repository). Usage: fetch-nodesets.sh TARGET_DIR
# Idempotent: does nothing when TARGET_DIR already holds this version.
set -euo pipefail
package="node-opcua-nodesets"
version="2.185.0"   # keep equal to app/plant/nodesets.py NODESETS_VERSION
files=(Opc.Ua.Di.NodeSet2.xml Opc.Ua.IA.NodeSet2.xml Opc.Ua.Machinery.NodeSet2.xml
       opc.ua.isa95-jobcontrol.nodeset2.xml Opc.Ua.Machinery.Jobs.Nodeset2.xml
       Opc.Ua.Woodworking.NodeSet2.xml)
target="${1:?usage: fetch-nodesets.sh TARGET_DIR}"
if [ -f "$target/.version" ] && [ "$(cat "$target/.version")" = "$version" ]; then
  exit 0
fi
if ! command -v npm >/dev/null 2>&1; then
  echo "stave: npm is needed to fetch the OPC UA information models ($package@$version)" >&2
  exit 2
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
(cd "$work" && npm pack --silent "$package@$version" >/dev/null)
tar -xzf "$work/$package-$version.tgz" -C "$work"
mkdir -p "$target"
for f in "${files[@]}"; do
  install -m 0644 "$work/package/nodesets/$f" "$target/$f"
done
install -m 0644 "$work/package/LICENSE" "$target/LICENSE" 2>/dev/null || true
echo "$version" > "$target/.version"
