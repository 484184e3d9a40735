#!/usr/bin/python3
"""Unpacks the OBJ models of Debian's sweethome3d-furniture into datasets/corpus/sweethome3d/
(git-ignored, optional data): about 820 furniture and character models (BlendSwap CC0 and
CC-BY, Scopia, KatorLegaz, Reallusion), each inside a .sh3f zip catalog with its materials and
textures. Only the .obj files are written (the materials and textures are not read: crossdiv
refines geometry and texture coordinates), one file per model, named
CATALOG/PATH_IN_THE_ARCHIVE with its folders joined by '__', so every name is unique and stable.

    install_sweethome3d_corpus.py [--catalogs DIR]

Exit status: 0 with the models written (or already there); 1 when the package is not installed
(run.sh installs it for ./run.sh corpus); 2 for an archive that does not read as a zip.
"""
import os
import shutil
import sys
import zipfile

CATALOGS = "/usr/share/sweethome3d/furniture"
HERE = os.path.dirname(os.path.abspath(__file__))
TARGET = os.path.join(HERE, "corpus", "sweethome3d")


def main(argv):
    catalogs = argv[2] if len(argv) == 3 and argv[1] == "--catalogs" else CATALOGS
    archives = sorted(f for f in os.listdir(catalogs) if f.endswith(".sh3f")) if os.path.isdir(catalogs) else []
    if not archives:
        print(f"no .sh3f catalog in {catalogs} (Debian package sweethome3d-furniture)", file=sys.stderr)
        return 1
    part = TARGET + ".part"  # whole or absent: a run stopped half-way leaves no partial corpus
    shutil.rmtree(part, ignore_errors=True)
    written = 0
    for archive in archives:
        name = os.path.splitext(archive)[0]
        try:
            with zipfile.ZipFile(os.path.join(catalogs, archive)) as z:
                for entry in z.infolist():
                    if entry.is_dir() or not entry.filename.lower().endswith(".obj"):
                        continue
                    out = os.path.join(part, name, entry.filename.replace("/", "__"))
                    os.makedirs(os.path.dirname(out), exist_ok=True)
                    with z.open(entry) as src, open(out, "wb") as dst:
                        shutil.copyfileobj(src, dst)
                    written += 1
        except zipfile.BadZipFile as e:
            print(f"{catalogs}/{archive}: not a zip archive: {e}", file=sys.stderr)
            return 2
    shutil.rmtree(TARGET, ignore_errors=True)
    os.rename(part, TARGET)
    print(f"{written} Sweet Home 3D models in {TARGET} from {len(archives)} catalogs")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
