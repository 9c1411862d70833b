# SPDX-License-Identifier: BSL-1.0
# Shared by scripts/check and scripts/demo (source it; it does nothing on its own).

# Everything a build, test, benchmark or demo of seawire needs, from Debian 12.
seawire_packages=(cmake g++ clang libclang-rt-14-dev clang-format clang-tidy catch2 libfmt-dev
  libbenchmark-dev libcli11-dev nlohmann-json3-dev libasio-dev ninja-build python3 librsvg2-bin
  gpsd gpsd-clients socat g++-aarch64-linux-gnu qemu-user)

seawire_root=$(cd -- "$(dirname -- "${BASH_SOURCE[0]}")/.." && pwd)

seawire_log() { printf '==> %s\n' "$*"; }

# Installs whichever of seawire_packages is missing, with apt-get, as root or through sudo.
seawire_install_packages() {
  local missing=() pkg
  for pkg in "${seawire_packages[@]}"; do
    if [[ "$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null)" != "install ok installed" ]]; then
      missing+=("$pkg")
    fi
  done
  if ((${#missing[@]} == 0)); then
    return 0
  fi
  local as_root=()
  if ((EUID != 0)); then
    if ! command -v sudo >/dev/null; then
      echo "missing packages and not root: apt-get install ${missing[*]}" >&2
      return 1
    fi
    as_root=(sudo)
  fi
  seawire_log "installing ${missing[*]}"
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q </dev/null
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -q --no-install-recommends "${missing[@]}" </dev/null
}

# seawire_configure <build dir> <cmake options...>: configures with Ninja when it is there.
seawire_configure() {
  local dir=$1
  shift
  local generator="Unix Makefiles"
  if command -v ninja >/dev/null; then
    generator=Ninja
  fi
  # A build tree made by another generator cannot be reused: start it again.
  if [[ -f "$dir/CMakeCache.txt" ]] &&
    ! grep -qx "CMAKE_GENERATOR:INTERNAL=$generator" "$dir/CMakeCache.txt"; then
    rm -rf -- "$dir"
  fi
  cmake -S "$seawire_root" -B "$dir" -G "$generator" "$@"
}
