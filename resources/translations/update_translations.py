#!/usr/bin/env python3
"""Refresh the .ts files from the sources and keep every translation a moved string already had.

    python3 resources/translations/update_translations.py

lupdate files a string under the class it is translated in; when code moves to another class
the string comes back "unfinished" in the new context. This runs lupdate (dropping vanished
entries) and then fills each unfinished message whose source text (and comment and plural
form) already had a translation anywhere in the old file. It prints what is still untranslated
and exits 1 if anything is.
"""
import copy
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
LUPDATE = os.environ.get("LUPDATE", "/usr/lib/qt6/bin/lupdate")


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


def update(ts_path):
    before = known_translations(ET.parse(ts_path))
    subprocess.run([LUPDATE, "-no-obsolete", "-locations", "relative", "src", "ui", "-ts",
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
    missing = []
    for name in sorted(os.listdir(HERE)):
        if name.endswith(".ts"):
            missing += update(os.path.join(HERE, name))
    for m in missing:
        print("untranslated:", m)
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
