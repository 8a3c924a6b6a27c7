#!/usr/bin/env python3
"""Packs the built grass binaries with the shared libraries they load into .gpu/ (git-ignored),
for a run on a GPU machine that has a driver but none of our Debian libraries (issue 29 item 4).

OpenImageIO links some 250 libraries for formats grass never reads there (video, DICOM, GDAL,
OpenVDB, ...): 370 MB, far over what such a run may carry. Those libraries are replaced by
stubs: same soname, same exported symbols and versions (so the loader, which binds
OpenImageIO's symbols at start, is satisfied), every function a trap (ud2) should one ever be
called. PNG, JPEG, OpenEXR and the rest of what grass uses stay real.

glibc and libstdc++ go to .gpu/compat/, used by .ci/gpu/run.sh only where the machine's own are
older than Debian 12's.

usage: .ci/gpu/pack.py [BUILD_DIR]   (default: build)
"""
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.path.join(ROOT, sys.argv[1] if len(sys.argv) > 1 else "build")
OUT = os.path.join(ROOT, ".gpu")
BINARIES = ["grass", "grass_gl_tests"]
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
# Loaded with dlopen by libepoxy and glvnd, so no NEEDED entry names them.
DLOPENED = ["libEGL.so.1", "libOpenGL.so.0", "libGLdispatch.so.0", "libGL.so.1"]
COMPAT = {"libc.so.6", "libm.so.6", "ld-linux-x86-64.so.2", "libpthread.so.0", "libdl.so.2",
          "librt.so.1", "libresolv.so.2", "libutil.so.1", "libgcc_s.so.1", "libstdc++.so.6"}
STUBBED = {"libopencv_core.so.406", "libopencv_imgproc.so.406", "libopencv_videoio.so.406",
           "libdcmimage.so.17", "libdcmimgle.so.17", "libdcmdata.so.17", "liboflog.so.17",
           "libofstd.so.17", "libavcodec.so.59", "libavformat.so.59", "libavutil.so.57",
           "libswscale.so.6", "libgif.so.7", "libheif.so.1", "libopenjp2.so.7",
           "libopenvdb.so.10.0", "libraw_r.so.20", "libwebp.so.7", "libwebpdemux.so.2",
           "libOpenColorIO.so.2.1", "libfreetype.so.6", "libtiff.so.6"}


def run(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def library_paths():
    paths = {}
    for line in run("ldconfig", "-p").splitlines():
        m = re.match(r"\s+(\S+) \(libc6,x86-64[^)]*\) => (\S+)", line)
        if m and m.group(1) not in paths:
            paths[m.group(1)] = m.group(2)
    return paths


def needed(path):
    return re.findall(r"\(NEEDED\)\s+Shared library: \[(.+?)\]", run("readelf", "-d", path))


def imported(path):
    """The symbol names `path` leaves undefined (what the loader binds from other libraries)."""
    names = set()
    for line in run("readelf", "--dyn-syms", "-W", path).splitlines():
        f = line.split()
        if len(f) >= 8 and f[0].endswith(":") and f[6] == "UND":
            names.add(f[7].split("@")[0])
    return names


def write_stub(soname, real, folder, wanted):
    """A library exporting those of `real`'s symbols that the pack imports, under their
    versions, each function a trap."""
    symbols = []  # (name, version or None, default version?, kind, size)
    for line in run("readelf", "--dyn-syms", "-W", real).splitlines():
        f = line.split()
        if len(f) < 8 or not f[0].endswith(":") or f[6] in ("UND", "ABS"):
            continue
        if f[4] not in ("GLOBAL", "WEAK") or f[3] not in ("FUNC", "IFUNC", "OBJECT", "TLS"):
            continue
        name, version, default = f[7], None, True
        if "@@" in name:
            name, version = name.split("@@")
        elif "@" in name:
            name, version = name.split("@")
            default = False
        if name not in wanted:
            continue
        size = int(f[2], 0) if f[2].startswith("0x") else int(f[2])
        symbols.append((name, version, default, f[3], size))
    versions = re.findall(r"Flags: (\S+)\s+Index: \d+\s+Cnt: \d+\s+Name: (\S+)",
                          run("readelf", "-V", "-W", real))
    nodes = [name for flags, name in versions if flags != "BASE"]
    asm, script = [], {node: [] for node in nodes}
    for i, (name, version, default, kind, size) in enumerate(symbols):
        label = f'"{name}"' if default else f"__grass_stub_{i}"
        if kind == "OBJECT":
            asm.append(f'.data\n.globl {label}\n.type {label},@object\n.size {label},{max(size, 1)}\n'
                       f'{label}: .zero {max(size, 1)}')
        elif kind == "TLS":
            asm.append(f'.section .tbss,"awT",@nobits\n.globl {label}\n.type {label},@tls_object\n'
                       f'.size {label},{max(size, 1)}\n{label}: .zero {max(size, 1)}')
        else:
            asm.append(f".text\n.globl {label}\n.type {label},@function\n"
                       f"{label}: lea __grass_stub_zeros(%rip), %rax\n ret")
        if not default:
            asm.append(f".symver {label}, {name}@{version}")
        elif version in script:
            script[version].append(f'"{name}"')
    # Every function returns the address of zeroed memory: an empty string to the plugins that
    # ask a library for its version at start, a null-filled struct or a non-zero int elsewhere.
    asm.append(".section .bss\n.balign 64\n__grass_stub_zeros: .zero 4096")
    base = os.path.join(folder, "stub-" + soname)
    with open(base + ".s", "w") as f:
        f.write("\n".join(asm) + "\n")
    args = ["gcc", "-shared", "-nostdlib", "-o", os.path.join(folder, soname),
            f"-Wl,-soname,{soname}", base + ".s"]
    if nodes:
        with open(base + ".map", "w") as f:
            for node in nodes:
                body = " ".join(s + ";" for s in script[node])
                f.write(f"{node} {{ global: {body} }};\n" if body else f"{node} {{ }};\n")
        args.append(f"-Wl,--version-script={base}.map")
    run(*args)
    os.remove(base + ".s")
    if nodes:
        os.remove(base + ".map")
    return len(symbols)


def main():
    shutil.rmtree(OUT, ignore_errors=True)
    for sub in ("bin", "lib", "compat"):
        os.makedirs(os.path.join(OUT, sub))
    paths = library_paths()
    queue, seen = list(DLOPENED), set()
    for binary in BINARIES:
        target = os.path.join(OUT, "bin", binary)
        run("strip", "-o", target, os.path.join(BUILD, "bin", binary))
        queue += needed(target)
    real, stubs, compat, loaded = 0, [], 0, []
    while queue:
        soname = queue.pop()
        if soname in seen:
            continue
        seen.add(soname)
        source = paths.get(soname)
        if source is None:
            sys.exit(f"pack.py: {soname} is not in the loader's cache (ldconfig -p)")
        if soname in COMPAT:
            shutil.copy(source, os.path.join(OUT, "compat", soname))
            compat += 1
        elif soname in STUBBED:
            stubs.append((soname, source))
        else:
            run("strip", "--strip-unneeded", "-o", os.path.join(OUT, "lib", soname), source)
            loaded.append(os.path.join(OUT, "lib", soname))
            real += 1
            queue += needed(source)
    wanted = set()
    for path in loaded + [os.path.join(OUT, "bin", b) for b in BINARIES]:
        wanted |= imported(path)
    exported = sum(write_stub(soname, source, os.path.join(OUT, "lib"), wanted)
                   for soname, source in stubs)
    # The UI font (fonts-dejavu-core): grass bench times the editor's panels, the GL tests draw them.
    os.makedirs(os.path.join(OUT, "fonts"))
    shutil.copy(FONT, os.path.join(OUT, "fonts"))
    # The binaries read shaders and test data from the source tree they were built from.
    with open(os.path.join(OUT, "source_dir"), "w") as f:
        f.write(ROOT + "\n")
    size = sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(OUT) for f in fs)
    print(f"pack.py: {OUT}: {len(BINARIES)} binaries, {real} libraries, {len(stubs)} stubs, "
          f"({exported} symbols), {compat} compat libraries, {size / 2**20:.1f} MiB")


if __name__ == "__main__":
    main()
