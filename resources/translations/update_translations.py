#!/usr/bin/env python3
"""Refresh the .ts files from the sources and keep every translation a moved string already had.

    python3 resources/translations/update_translations.py          # refresh the .ts files
    python3 resources/translations/update_translations.py --check  # fail if they are stale

lupdate files a string under the class it is translated in; when code moves to another class
the string comes back "unfinished" in the new context. This runs lupdate (dropping vanished
entries) and then fills each unfinished message whose source text (and comment and plural
form) already had a translation anywhere in the old file. It prints what is still untranslated
and exits 1 if anything is.
"""
import copy
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
LUPDATE = os.environ.get("LUPDATE", "/usr/lib/qt6/bin/lupdate")
# The core marks the English text the app translates with a Qt-free no-op of its own
# (src/core/common/translate_marker.h).
ALIAS = ["-tr-function-alias", "QT_TRANSLATE_NOOP+=CAM_TRANSLATE_NOOP"]


def key(message):
    source = message.findtext("source") or ""
    comment = message.findtext("comment") or ""
    return source, comment, message.get("numerus") == "yes"


def known_translations(tree):
    out = {}
    for message in tree.iter("message"):
        translation = message.find("translation")
        if translation is None or translation.get("type") in ("unfinished",):
            continue
        if (translation.text or "").strip() or len(translation):
            out.setdefault(key(message), copy.deepcopy(translation))
    return out


def messages(tree):
    return {(c.findtext("name"), m.findtext("source"), m.findtext("comment") or "")
            for c in tree.iter("context") for m in c.iter("message")}


def check(ts_path):
    """What lupdate would extract now that the committed file lacks or leaves unfinished."""
    committed = ET.parse(ts_path)
    with tempfile.TemporaryDirectory() as tmp:
        fresh_path = os.path.join(tmp, os.path.basename(ts_path))
        shutil.copy(ts_path, fresh_path)
        subprocess.run([LUPDATE, *ALIAS, "-no-obsolete", "-locations", "none", os.path.join(ROOT, "src"),
                        os.path.join(ROOT, "ui"), "-ts", fresh_path], check=True,
                       stdout=subprocess.DEVNULL)
        fresh = ET.parse(fresh_path)
    problems = [f"not in {os.path.basename(ts_path)}: {c}: {s!r}"
                for c, s, _ in sorted(messages(fresh) - messages(committed))]
    problems += [f"unfinished: {c.findtext('name')}: {m.findtext('source')!r}"
                 for c in fresh.iter("context") for m in c.iter("message")
                 if m.find("translation") is not None
                 and m.find("translation").get("type") == "unfinished"]
    return problems


def update(ts_path):
    before = known_translations(ET.parse(ts_path))
    subprocess.run([LUPDATE, *ALIAS, "-no-obsolete", "-locations", "relative", "src", "ui", "-ts",
                    os.path.relpath(ts_path, ROOT)], cwd=ROOT, check=True,
                   stdout=subprocess.DEVNULL)
    tree = ET.parse(ts_path)
    missing = []
    for context in tree.iter("context"):
        for message in context.iter("message"):
            translation = message.find("translation")
            if translation is None or translation.get("type") != "unfinished":
                continue
            known = before.get(key(message))
            if known is None:
                missing.append(f"{context.findtext('name')}: {message.findtext('source')}")
                continue
            message.remove(translation)
            filled = copy.deepcopy(known)
            filled.attrib.pop("type", None)
            message.append(filled)
    tree.write(ts_path, encoding="utf-8", xml_declaration=True)
    with open(ts_path, "a", encoding="utf-8") as f:
        f.write("\n")
    return missing


def main():
    checking = "--check" in sys.argv[1:]
    missing = []
    for name in sorted(os.listdir(HERE)):
        if name.endswith(".ts"):
            path = os.path.join(HERE, name)
            missing += check(path) if checking else update(path)
    for m in missing:
        print("untranslated:" if not checking else "stale:", m)
    if missing and checking:
        print("run: python3 resources/translations/update_translations.py, then translate")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
