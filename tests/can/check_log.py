#!/usr/bin/python3
"""Decode can_run's candump log with the DBC (python3-canmatrix) and check it against the CSV
of the values the application computed (docs/can.md).

  check_log.py --run CAN_RUN --dbc inclino.dbc --work DIR --log2asc LOG2ASC [--speed-loss A:B]

Checks, each a failure when it does not hold:
  - can_run ends with status=ok, unmapped=0, tx_errors=0, and its frame count is the CSV's;
  - every log line is the candump -l format, timestamps non-decreasing;
  - log2asc (can-utils) converts the log, one ASC event line per frame;
  - every transmitted frame, decoded with the DBC, has the CSV row's identifier and each signal
    within one LSB of the application's value (values rounded to nearest: <= 0.5 LSB; bounds
    rounded up: in [value, value + 1 LSB)); valid, mode, the speed flag and the fault word exact;
  - an independent E2E Profile 1 check of every frame (CRC-8 J1850 over the data ID, low byte
    first, and bytes 1..7, start 0, no final XOR) and its counter (+1 mod 15 per identifier,
    never 15);
  - while the speed input is lost in DRIVING, no attitude frame is valid and the fault word says so.
Prints one summary line: summary: tool=check_log status=ok|fail frames=N ...
"""
import argparse
import csv
import os
import re
import subprocess
import sys

import canmatrix
import canmatrix.formats

DATA_ID = {0x310: 0x1310, 0x311: 0x1311, 0x312: 0x1312, 0x1A0: 0x11A0}
LINE = re.compile(r"^\((\d{10})\.(\d{6})\) (\w+) ([0-9A-F]{3})#((?:[0-9A-F]{2}){0,8})$")
FAULT_SPEED = 1 << 24

failures = []


def fail(msg):
    failures.append(msg)
    if len(failures) <= 20:
        print("FAIL:", msg)


def crc8_p01(data_id, frame):
    reg = 0x00
    for b in [data_id & 0xFF, data_id >> 8] + list(frame[1:]):
        reg ^= b
        for _ in range(8):
            reg = ((reg << 1) ^ 0x1D) & 0xFF if reg & 0x80 else (reg << 1) & 0xFF
    return reg


def summary_of(text):
    last = [ln for ln in text.splitlines() if ln.startswith("summary:")]
    if not last:
        return {}
    return dict(kv.split("=", 1) for kv in last[-1].split()[1:] if "=" in kv)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--run", required=True)
    ap.add_argument("--dbc", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--log2asc", required=True)
    ap.add_argument("--speed-loss", default="12:14")
    ap.add_argument("--scenario", default="braking")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    log = os.path.join(a.work, "can_run.log")
    csvp = os.path.join(a.work, "can_run.csv")
    r = subprocess.run([a.run, "--log", log, "--csv", csvp, "--scenario", a.scenario,
                        "--speed-loss", a.speed_loss], capture_output=True, text=True)
    sys.stdout.write(r.stdout)
    sm = summary_of(r.stdout)
    if r.returncode != 0 or sm.get("status") != "ok":
        fail("can_run failed: rc %d, %s" % (r.returncode, r.stderr.strip()))
    for k in ("unmapped", "tx_errors"):
        if sm.get(k) != "0":
            fail("can_run %s=%s" % (k, sm.get(k)))

    db = canmatrix.formats.loadp_flat(a.dbc)
    frames_db = {fr.arbitration_id.id: fr for fr in db.frames}
    for fid in DATA_ID:
        if fid not in frames_db:
            fail("the DBC has no frame 0x%03X" % fid)

    with open(log) as f:
        lines = f.read().splitlines()
    rows = list(csv.DictReader(open(csvp)))
    if sm.get("frames") != str(len(rows)):
        fail("summary frames=%s, CSV rows %d" % (sm.get("frames"), len(rows)))

    # log2asc validates the format: one event line per frame
    asc = subprocess.run([a.log2asc, "-I", log, "can0"], capture_output=True, text=True)
    ev = [ln.split() for ln in asc.stdout.splitlines()
          if re.match(r"^\s*\d+\.\d+\s+\d+\s+[0-9A-Fa-f]+\s+Rx", ln)]
    headers = sum(1 for ln in asc.stdout.splitlines() if ln.startswith("date "))
    if asc.returncode != 0 or len(ev) != len(lines) or headers != 1:
        fail("log2asc: rc %d, %d events for %d lines, %d headers" % (
            asc.returncode, len(ev), len(lines), headers))
    else:
        # the ASC times are relative to the first frame, the identifiers and bytes the log's
        t0 = None
        for e, ln in zip(ev, lines):
            m = LINE.match(ln)
            if not m:
                continue
            t = int(m.group(1)) + int(m.group(2)) * 1e-6
            t0 = t if t0 is None else t0
            data = bytes.fromhex(m.group(5))
            if (abs(float(e[0]) - (t - t0)) > 1.5e-6 or int(e[2], 16) != int(m.group(4), 16) or
                    bytes(int(x, 16) for x in e[6:6 + len(data)]) != data):
                fail("log2asc event %r does not match %r" % (" ".join(e), ln))
                break

    last_t = -1.0
    counters = {}
    tx = []
    n_speed = 0
    for i, ln in enumerate(lines):
        m = LINE.match(ln)
        if not m:
            fail("line %d is not candump -l: %r" % (i + 1, ln))
            continue
        t = int(m.group(1)) + int(m.group(2)) * 1e-6
        if t < last_t:
            fail("line %d: time goes back" % (i + 1))
        last_t = t
        fid = int(m.group(4), 16)
        data = bytes.fromhex(m.group(5))
        if fid not in DATA_ID or len(data) != 8:
            fail("line %d: unexpected frame %03X dlc %d" % (i + 1, fid, len(data)))
            continue
        if data[0] != crc8_p01(DATA_ID[fid], data):
            fail("line %d: E2E CRC %02X, expected %02X" % (i + 1, data[0], crc8_p01(DATA_ID[fid], data)))
        c = data[1] & 0x0F
        if c == 15 or (fid in counters and c != (counters[fid] + 1) % 15):
            fail("line %d: counter %d after %s" % (i + 1, c, counters.get(fid)))
        counters[fid] = c
        if fid == 0x1A0:
            n_speed += 1
        else:
            tx.append((i + 1, fid, data))

    if len(tx) != len(rows):
        fail("%d transmitted frames in the log, %d CSV rows" % (len(tx), len(rows)))
    worst = {}
    n_loss_att = 0

    def near(name, got, want, lsb, bound=False):
        d = got - want
        if bound:
            ok = -1e-9 <= d < lsb + 1e-9
        else:
            ok = abs(d) <= 0.5 * lsb + 1e-9
        worst[name] = max(worst.get(name, 0.0), abs(d) / lsb)
        if not ok:
            fail("%s: decoded %.6f, application %.9f (lsb %g)" % (name, got, want, lsb))

    for (lno, fid, data), row in zip(tx, rows):
        if int(row["id"], 16) != fid:
            fail("line %d: id %03X, CSV %s" % (lno, fid, row["id"]))
            continue
        dec = frames_db[fid].decode(data)
        v = {k: float(s.phys_value) for k, s in dec.items()}
        mode, valid, speed_ok = int(row["mode"]), int(row["valid"]), int(row["speed_ok"])
        if fid == 0x310:
            near("Slope", v["Slope"], float(row["slope_deg"]), 0.01)
            near("Grade", v["Grade"], float(row["grade_pct"]), 0.01)
            near("SlopeBound", v["SlopeBound"], float(row["slope_bound_deg"]), 0.001, True)
            if int(v["SlopeValid"]) != valid or int(v["SlopeMode"]) != mode:
                fail("line %d: SlopeValid/SlopeMode" % lno)
        elif fid == 0x311:
            near("Roll", v["Roll"], float(row["roll_deg"]), 0.01)
            near("Pitch", v["Pitch"], float(row["pitch_deg"]), 0.01)
            near("AttBound", v["AttBound"], float(row["att_bound_deg"]), 0.001, True)
            if int(v["AttValid"]) != valid or int(v["AttMode"]) != mode:
                fail("line %d: AttValid %d / AttMode %d, CSV %d %d" % (lno, v["AttValid"], v["AttMode"], valid, mode))
            if not speed_ok:
                n_loss_att += 1
                if int(v["AttValid"]):
                    fail("line %d: attitude valid without the speed input" % lno)
        else:
            near("GradeBound", v["GradeBound"], float(row["grade_bound_pct"]), 0.01, True)
            fault = (int(row["app_flags"]) | (int(row["slope_flags"]) << 8) |
                     (int(row["att_fault"]) << 16) | (FAULT_SPEED if mode == 1 and not speed_ok else 0))
            if int(v["FaultWord"]) != fault:
                fail("line %d: FaultWord %08X, expected %08X" % (lno, int(v["FaultWord"]), fault))
            if int(v["Mode"]) != mode or int(v["SpeedInputOk"]) != speed_ok:
                fail("line %d: Mode/SpeedInputOk" % lno)
    if n_speed == 0:
        fail("no VEH_Speed frame in the log")
    if a.speed_loss and n_loss_att == 0:
        fail("no attitude frame during the speed loss")
    status = "ok" if not failures else "fail"
    print("summary: tool=check_log status=%s frames=%d tx=%d speed=%d loss_att=%d failures=%d %s" % (
        status, len(lines), len(tx), n_speed, n_loss_att, len(failures),
        " ".join("worst_%s_lsb=%.3f" % (k.lower(), w) for k, w in sorted(worst.items()))))
    return 0 if not failures else 1


if __name__ == "__main__":
    sys.exit(main())
