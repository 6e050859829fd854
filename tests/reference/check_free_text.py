#!/usr/bin/python3
"""Checks that exports carrying a hostile project name are still valid for their readers.

    check_free_text.py FOLDER [--points N] [--rs274 PATH]

Every file of FOLDER is checked by what its suffix says, with the programs and rules that read
such a file, none of them Camwright's:

  *.svg    parsed by expat (Python's xml.parsers.expat) and rendered by rsvg-convert;
  *.pdf    read by pdfinfo; its Title is one line without control characters;
  *.csv    a cam table read by Python's csv module: no CR anywhere, exactly 6 comment lines,
           the header and N rows of 4 numbers; no cell a spreadsheet would take for a formula
           (starting, after spaces, with = + - @) in any comment line, split at ',' or ';';
  *.st     IEC 61131-3 Structured Text of a CODESYS cam: comments (* *) closed and not nested,
           the rest exactly the VAR_GLOBAL block with two declarations whose names are
           identifiers by the standard's rule (letter or '_' then letters, digits and single
           '_', not ending in '_') and no keyword or type name of the standard or of CODESYS;
  *.ngc    a G-code program: printable ASCII only, every comment "( ... )" closed on its line
           with no parenthesis inside, no ';' outside one (it would comment out the rest of
           the line); run by LinuxCNC's rs274 when --rs274 is given.

Prints one line per problem; exits 0 when there is none, 1 otherwise.
"""

import argparse
import csv
import io
import os
import re
import subprocess
import sys
import xml.parsers.expat

problems = []


def fail(path, message):
    problems.append(f"{os.path.basename(path)}: {message}")


def check_svg(path):
    parser = xml.parsers.expat.ParserCreate()
    try:
        with open(path, "rb") as f:
            parser.ParseFile(f)
    except xml.parsers.expat.ExpatError as e:
        fail(path, f"expat refuses it: {e}")
        return
    r = subprocess.run(["rsvg-convert", "-f", "png", "-o", path + ".png", path],
                       capture_output=True, text=True)
    if r.returncode != 0:
        fail(path, f"rsvg-convert refuses it ({r.returncode}): {r.stderr.strip()[:300]}")


def check_pdf(path):
    r = subprocess.run(["pdfinfo", "-enc", "UTF-8", path], capture_output=True)
    if r.returncode != 0:
        fail(path, f"pdfinfo refuses it: {r.stderr.decode(errors='replace')[:300]}")
        return
    info = r.stdout.decode("utf-8", errors="strict")
    titles = [line for line in info.split("\n") if line.startswith("Title:")]
    if len(titles) != 1:
        fail(path, f"{len(titles)} Title lines in pdfinfo's output (a line break in the title?)")
        return
    if any(ord(c) < 0x20 or 0x7F <= ord(c) <= 0x9F for c in titles[0]):
        fail(path, f"a control character in the title: {titles[0]!r}")


FORMULA = re.compile(r"^[ \t]*[=+\-@]")


def check_camtable(path, points):
    data = open(path, "rb").read()
    if b"\r" in data:
        fail(path, "a carriage return")
    text = data.decode("utf-8")
    lines = text.split("\n")
    if lines[-1] != "":
        fail(path, "the last line has no line feed")
    lines = lines[:-1]
    comments = [line for line in lines if line.startswith("#")]
    if any(not line.startswith("#") for line in lines[:6]):
        fail(path, f"the first 6 lines are not all comments: {lines[:6]}")
    elif len(comments) != 12:
        # The header's 6, the source, and the 5 lines of the motion's characteristics.
        fail(path, f"{len(comments)} comment lines, not the 12 of the header")
    elif any(not line.startswith("#") for line in lines[:12]):
        fail(path, f"the comment lines are not all at the top: {lines[:12]}")
    for line in comments:
        for cell in re.split(r"[,;]", line):
            if FORMULA.match(cell):
                fail(path, f"a formula cell in a comment line: {cell[:60]!r}")
    rows = list(csv.reader(io.StringIO("\n".join(lines[len(comments):]) + "\n")))
    if not rows or rows[0] != ["master_deg", "position", "velocity_per_deg",
                               "acceleration_per_deg2"]:
        fail(path, f"not the cam table's header: {rows[:1]}")
        return
    if len(rows) - 1 != points:
        fail(path, f"{len(rows) - 1} rows, not {points}")
    for row in rows[1:]:
        if len(row) != 4:
            fail(path, f"a row of {len(row)} cells: {row[:6]}")
            return
        try:
            [float(v) for v in row]
        except ValueError:
            fail(path, f"a row that is not numbers: {row}")
            return


# IEC 61131-3 (third edition, Annex C) keywords, its elementary and generic types, the
# operators of Instruction List, and the CODESYS keywords and operators of its online help.
IEC_RESERVED = set("""
ABSTRACT ACTION END_ACTION ARRAY AT BY CASE END_CASE CLASS END_CLASS CONFIGURATION
END_CONFIGURATION CONSTANT CONTINUE DO ELSE ELSIF EN ENO EXIT EXTENDS F_EDGE FALSE FINAL FOR
END_FOR FROM FUNCTION END_FUNCTION FUNCTION_BLOCK END_FUNCTION_BLOCK IF END_IF IMPLEMENTS
INITIAL_STEP INTERFACE END_INTERFACE INTERNAL INTERVAL METHOD END_METHOD NAMESPACE
END_NAMESPACE NON_RETAIN NULL OF ON OVERLAP OVERRIDE PRIORITY PRIVATE PROGRAM END_PROGRAM
PROTECTED PUBLIC R_EDGE READ_ONLY READ_WRITE REF REF_TO REPEAT END_REPEAT RESOURCE
END_RESOURCE RETAIN RETURN SINGLE STEP END_STEP STRUCT END_STRUCT SUPER TASK THEN THIS TO
TRANSITION END_TRANSITION TRUE TYPE END_TYPE UNTIL USING VAR END_VAR VAR_ACCESS VAR_CONFIG
VAR_EXTERNAL VAR_GLOBAL VAR_IN_OUT VAR_INPUT VAR_OUTPUT VAR_TEMP WHILE END_WHILE WITH
AND OR XOR NOT MOD
BOOL SINT INT DINT LINT USINT UINT UDINT ULINT REAL LREAL TIME LTIME DATE LDATE TIME_OF_DAY TOD
LTIME_OF_DAY LTOD DATE_AND_TIME DT LDATE_AND_TIME LDT STRING WSTRING CHAR WCHAR BYTE WORD DWORD
LWORD ANY ANY_DERIVED ANY_ELEMENTARY ANY_MAGNITUDE ANY_NUM ANY_REAL ANY_INT ANY_UNSIGNED
ANY_SIGNED ANY_DURATION ANY_BIT ANY_CHARS ANY_STRING ANY_CHAR ANY_DATE T D
LD LDN ST STN S R ANDN ORN XORN ADD SUB MUL DIV GT GE EQ NE LE LT JMP JMPC JMPCN CAL CALC
CALCN RET RETC RETCN
POINTER REFERENCE UNION END_UNION VAR_INST VAR_STAT PERSISTENT AND_THEN OR_ELSE ADR BITADR
SIZEOF INI PROPERTY END_PROPERTY
MC_CAM_REF SMC_CAMXYVA MC_MOTIONFUNCTIONPOINT
""".split())
IDENTIFIER = re.compile(r"^(?:[A-Za-z]|_[A-Za-z0-9])(?:_?[A-Za-z0-9])*$")
NUMBER = r"-?[0-9]+\.[0-9]*(?:e[-+]?[0-9]+)?"


def strip_st_comments(path, text):
    out, i = [], 0
    while i < len(text):
        if text.startswith("(*", i):
            end = text.find("*)", i + 2)
            if end < 0:
                fail(path, "a comment that is never closed")
                return None
            if "(*" in text[i + 2:end]:
                fail(path, "a comment inside a comment")
                return None
            out.append(" ")
            i = end + 2
        elif text.startswith("*)", i):
            fail(path, "a comment closed that was never opened")
            return None
        else:
            out.append(text[i])
            i += 1
    return "".join(out)


def check_codesys(path, points):
    text = strip_st_comments(path, open(path, encoding="utf-8").read())
    if text is None:
        return
    knot = (rf"\(dX := {NUMBER}, dY := {NUMBER}, dV := {NUMBER}, dA := {NUMBER}\)")
    pattern = re.compile(
        r"^\s*VAR_GLOBAL\s+(?P<knots>\w+) : ARRAY\[0\.\.(?P<n>[0-9]+)\] OF SMC_CAMXYVA := \[\s*"
        rf"{knot}(?:,\s*{knot})*\s*\];\s*"
        r"(?P<cam>\w+) : MC_CAM_REF := \(xStart := 0\.0, xEnd := 360\.0, byType := 3, "
        r"byVarType := 6,\s*nElements := (?P<elements>[0-9]+), nTappets := 0, "
        r"pce := ADR\((?P<ref>\w+)\)\);\s*END_VAR\s*$")
    m = pattern.match(text)
    if not m:
        fail(path, "not the VAR_GLOBAL block of a cam once its comments are taken away")
        return
    for name in (m["knots"], m["cam"]):
        if not IDENTIFIER.match(name):
            fail(path, f"{name!r} is no IEC 61131-3 identifier")
        if name.upper() in IEC_RESERVED:
            fail(path, f"{name!r} is a reserved word")
    if m["ref"] != m["knots"] or m["knots"] == m["cam"]:
        fail(path, f"the cam {m['cam']!r} does not point at its knots {m['knots']!r}")
    if int(m["n"]) != points or int(m["elements"]) != points + 1:
        fail(path, f"ARRAY[0..{m['n']}] with nElements {m['elements']} for {points} points")


def check_beckhoff(path, points):
    """TwinCAT's MC_MotionFunctionPoint array: an IEC identifier that is no keyword, points
    numbered from 1 without gaps, points + 1 of them."""
    text = strip_st_comments(path, open(path, encoding="utf-8").read())
    if text is None:
        return
    point = (r"\(PointIndex := ([0-9]+), FunctionType := MOTIONFUNCTYPE_POLYNOM5_MM, "
             r"PointType := MOTIONPOINTTYPE_MOTION,\s*RelIndexNextPoint := 1, "
             rf"MasterPos := {NUMBER}, SlavePos := {NUMBER},\s*SlaveVelo := {NUMBER}, "
             rf"SlaveAcc := {NUMBER}, SlaveJerk := {NUMBER}\)")
    m = re.match(r"^\s*VAR_GLOBAL\s+(?P<id>\w+) : ARRAY\[1\.\.(?P<n>[0-9]+)\] OF "
                 rf"MC_MotionFunctionPoint := \[\s*(?P<points>{point}(?:,\s*{point})*)\s*\];"
                 r"\s*END_VAR\s*$", text)
    if not m:
        fail(path, "not the VAR_GLOBAL block of motion function points once its comments are "
                   "taken away")
        return
    if not IDENTIFIER.match(m["id"]) or m["id"].upper() in IEC_RESERVED:
        fail(path, f"{m['id']!r} is no IEC 61131-3 identifier or a reserved word")
    indices = [int(i) for i in re.findall(r"PointIndex := ([0-9]+)", m["points"])]
    if indices != list(range(1, points + 2)) or int(m["n"]) != points + 1:
        fail(path, f"points numbered {indices[:3]}…, ARRAY[1..{m['n']}], for {points} points")


# Logix tag names: a letter or underscore first, then letters, digits and single underscores,
# no underscore last, at most 40 characters (the name plus "_profile" for the CAM_PROFILE).
LOGIX_TAG = re.compile(r"^[A-Za-z_](?:_?[A-Za-z0-9])*$")


def check_rockwell(path, points):
    """Logix Structured Text filling a CAM array: one tag, elements 0 … points, cubic."""
    text = strip_st_comments(path, open(path, encoding="utf-8").read())
    if text is None:
        return
    statement = re.compile(rf"^(\w+)\[([0-9]+)\]\.Master := {NUMBER}; \1\[\2\]\.Slave := "
                           rf"{NUMBER}; \1\[\2\]\.SegmentType := 1;$")
    names, indices = set(), []
    for line in text.split("\n"):
        if not line.strip():
            continue
        m = statement.match(line)
        if not m:
            fail(path, f"not a statement filling the CAM array: {line[:80]!r}")
            return
        names.add(m[1])
        indices.append(int(m[2]))
    if len(names) != 1:
        fail(path, f"the elements of {len(names)} tags")
        return
    name = names.pop()
    if not LOGIX_TAG.match(name) or len(name) + len("_profile") > 40 or \
            name.upper() in IEC_RESERVED | {"CAM", "CAM_PROFILE"}:
        fail(path, f"{name!r} is no Logix tag name")
    if indices != list(range(points + 1)):
        fail(path, f"elements {indices[:3]}… for {points} points")


def check_kollmorgen(path, points):
    """KAS IDE's cam profile CSV: its fixed lines and points + 1 rows X;Y;SPLINE, nothing of the
    name (the format has no comments)."""
    data = open(path, "rb").read()
    if b"\r" in data or not data.endswith(b"\n"):
        fail(path, "a carriage return, or no line feed at the end")
    lines = data.decode("ascii", errors="replace").split("\n")[:-1]
    if lines[:2] != ["CYCLIC;YES;", "TABLE_BEGIN;;"] or lines[-1:] != ["TABLE_END;;"]:
        fail(path, f"not a KAS cam profile: {lines[:2]} … {lines[-1:]}")
        return
    rows = lines[2:-1]
    if len(rows) != points + 1:
        fail(path, f"{len(rows)} rows, not {points + 1}")
    for row in rows:
        cells = row.split(";")
        try:
            ok = len(cells) == 3 and cells[2] == "SPLINE" and [float(v) for v in cells[:2]]
        except ValueError:
            ok = False
        if not ok:
            fail(path, f"not a row X;Y;SPLINE: {row[:80]!r}")
            return


def check_gcode(path, rs274):
    data = open(path, "rb").read()
    if any(b < 0x20 and b != 0x0A or b >= 0x7F for b in data):
        fail(path, "a byte that is not printable ASCII")
    for number, line in enumerate(data.decode("ascii", errors="replace").split("\n"), 1):
        depth = 0
        for c in line:
            if c == ";" and depth == 0:
                fail(path, f"line {number}: ';' starts a comment to the end of the line: {line!r}")
                break
            if c == "(":
                depth += 1
                if depth > 1:
                    fail(path, f"line {number}: '(' inside a comment: {line!r}")
            elif c == ")":
                depth -= 1
                if depth < 0:
                    fail(path, f"line {number}: ')' outside a comment: {line!r}")
        if depth > 0:
            fail(path, f"line {number}: a comment not closed on its line: {line!r}")
    if rs274:
        canon = path + ".canon"
        r = subprocess.run([rs274, path, canon], capture_output=True, text=True)
        if r.returncode != 0:
            fail(path, f"rs274 refuses it ({r.returncode}): {(r.stdout + r.stderr)[-300:]}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("folder")
    parser.add_argument("--points", type=int, default=360)
    parser.add_argument("--rs274")
    args = parser.parse_args()
    checked = 0
    for name in sorted(os.listdir(args.folder)):
        path = os.path.join(args.folder, name)
        if name.endswith(".svg"):
            check_svg(path)
        elif name.endswith(".pdf"):
            check_pdf(path)
        elif name.endswith(".kollmorgen.csv"):
            check_kollmorgen(path, args.points)
        elif name.endswith(".csv"):
            check_camtable(path, args.points)
        elif name.endswith(".beckhoff.st"):
            check_beckhoff(path, args.points)
        elif name.endswith(".rockwell.st"):
            check_rockwell(path, args.points)
        elif name.endswith(".st"):
            check_codesys(path, args.points)
        elif name.endswith(".ngc"):
            check_gcode(path, args.rs274)
        else:
            continue
        checked += 1
    for p in problems:
        print(p)
    print(f"{checked} files checked, {len(problems)} problems", file=sys.stderr)
    return 1 if problems or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
