#!/bin/sh
# Install the missing Debian packages (as root) or print the exact command.
missing=""
for p in "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
line="apt-get install -y --no-install-recommends$missing"
if [ "$(id -u)" = 0 ]; then
  echo "lac: installing missing Debian packages:$missing"
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive $line -qq || {
    echo "lac: package installation failed; run: $line" >&2; exit 1; }
else
  echo "lac: missing Debian packages. Run as root:" >&2
  echo "  apt-get update && $line" >&2
  exit 1
fi
