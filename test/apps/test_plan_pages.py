#!/usr/bin/python3
"""The 3-D plan pages (--html) of ompl_mm_plan (MOBILE BLOCKED, KUKA TABLE, KUKA CABINET, a Franka
Panda with visual meshes picking a cylinder) and ompl_phys_plan, loaded in headless Chromium: the
page draws its first picture with no JavaScript error or warning, names the current segment, and its
screenshots at the start and the middle of the timeline differ from each other and from a blank page.
A MOBILE BLOCKED page stays under 2 MB, the Panda's (its visual meshes reduced) under 3 MB.
Needs Debian's chromium and python3-matplotlib (PNG reading).

Prints "ok - name" / "not ok - name" per check, then "N passed, M failed"; exits 1 on any failure.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

import matplotlib.image

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--hide-scrollbars", "--window-size=1000,700", "--virtual-time-budget=3000"]
MAX_PAGE_BYTES = 2 * 1024 * 1024
MAX_PANDA_PAGE_BYTES = 3 * 1024 * 1024
# a Franka Panda (scenes/robots/panda) moving a cylinder from one table to another; {robots} is its folder
PANDA_SCENE = """<scene name="panda_pick" time_limit="60">
  <robot urdf="{robots}/panda.urdf" srdf="{robots}/panda.srdf" group="panda_arm" tool_link="panda_grasptarget">
    <fixed_joint name="panda_finger_joint1" value="0.04"/>
  </robot>
  <obstacle name="floor"><origin xyz="0 0 -0.035"/><box size="2 2 0.05"/></obstacle>
  <obstacle name="table1_top"><origin xyz="0.5 0 0.405"/><box size="0.54 0.54 0.05"/></obstacle>
  <obstacle name="table2_top"><origin xyz="0.2 -0.6 0.405"/><box size="0.54 0.54 0.05"/></obstacle>
  <surface name="table1" height="0.43" min="0.25 -0.25" max="0.75 0.25" obstacle="table1_top"/>
  <surface name="table2" height="0.43" min="-0.05 -0.75" max="0.45 -0.35" obstacle="table2_top"/>
  <region name="air" min="-0.2 -0.65 0.45" max="0.7 0.25 0.95"/>
  <object name="cyl1"><cylinder radius="0.03" length="0.07"/></object>
  <start><robot state="ready"/><object name="cyl1" xyz="0.55 0.1 0.43"/></start>
  <goal><robot state="ready" tolerance="0.01"/><object name="cyl1" xyz="0.2 -0.5 0.43" tolerance="0.01"/></goal>
  <primitives><transit/><pickup lift_height="0.10" approach_distance="0.05"/><transfer_rigid approach_distance="0.05"/></primitives>
</scene>
"""
# a screenshot "differs" from another when this share of its pixels does
MIN_CHANGED_SHARE = 0.002


class Checks:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, name, condition, *details):
        print(("ok - " if condition else "not ok - ") + name)
        if condition:
            self.passed += 1
        else:
            self.failed += 1
            for detail in details:
                for line in str(detail).splitlines():
                    print(f"#   {line}")
        return condition


def chromium(args):
    done = subprocess.run(["chromium", *CHROMIUM_FLAGS, *args], capture_output=True, text=True, timeout=120)
    return done.stdout


def page_state(page, hash_part):
    """(ready, problems, status) of the page after it loaded at hash_part, read from its DOM."""
    dom = chromium(["--dump-dom", f"file://{page}#{hash_part}"])
    ready = re.search(r'<body[^>]*data-ready="1"', dom) is not None
    problems = re.search(r'<pre id="problems"[^>]*>(.*?)</pre>', dom, re.S)
    status = re.search(r'<span id="status">(.*?)</span>', dom, re.S)
    return ready, problems.group(1).strip() if problems else "(no #problems element)", status.group(1) if status else ""


def screenshot(page, hash_part, png):
    chromium([f"--screenshot={png}", f"file://{page}#{hash_part}"])
    return matplotlib.image.imread(png)


def changed_share(a, b):
    """The share of pixels that differ between two screenshots of one size."""
    if a.shape != b.shape:
        return 1.0
    return float((abs(a - b).max(axis=2) > 0.02).mean())


def check_page(checks, name, page, segment_pattern, blank):
    ready, problems, status = page_state(page, "at=0.5&paused")
    checks.check(f"{name}: the page draws with no JavaScript error or warning",
                 ready and problems == "", f"ready: {ready}", f"problems: {problems}")
    checks.check(f"{name}: the middle of the timeline names its segment",
                 re.match(segment_pattern, status) is not None, f"status: {status!r}")
    start = screenshot(page, "at=0&paused", page + ".start.png")
    middle = screenshot(page, "at=0.5&paused", page + ".middle.png")
    checks.check(f"{name}: screenshots at the start and the middle differ",
                 changed_share(start, middle) > MIN_CHANGED_SHARE, f"changed: {changed_share(start, middle):.4f}")
    checks.check(f"{name}: the screenshots differ from a blank page",
                 min(changed_share(start, blank), changed_share(middle, blank)) > 20 * MIN_CHANGED_SHARE,
                 f"start: {changed_share(start, blank):.4f}, middle: {changed_share(middle, blank):.4f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    for option in ["--mm-plan", "--phys-plan", "--scenes", "--scratch"]:
        parser.add_argument(option, required=True)
    args = parser.parse_args()
    shutil.rmtree(args.scratch, ignore_errors=True)
    os.makedirs(args.scratch)
    checks = Checks()
    if not checks.check("chromium is installed", shutil.which("chromium") is not None):
        return 1

    blank_page = os.path.join(args.scratch, "blank.html")
    with open(blank_page, "w") as f:
        f.write('<!DOCTYPE html><html><body style="margin:0;background:#f7f7f4"></body></html>')
    blank = screenshot(blank_page, "", blank_page + ".png")

    mm_page = os.path.join(args.scratch, "mobile_blocked.html")
    done = subprocess.run([args.mm_plan, os.path.join(args.scenes, "mobile_blocked.xml"), "--seed", "1",
                           "--html", mm_page], capture_output=True, text=True, timeout=300)
    checks.check("ompl_mm_plan --html writes the page", done.returncode == 0 and os.path.isfile(mm_page),
                 done.stderr)
    size = os.path.getsize(mm_page) if os.path.isfile(mm_page) else 0
    checks.check(f"the MOBILE BLOCKED page is under 2 MB ({size} bytes)", 0 < size < MAX_PAGE_BYTES)
    check_page(checks, "MOBILE BLOCKED", mm_page, r"(transit|push obj\d) — [\d.]+ s of [\d.]+ s$", blank)

    arm_page = os.path.join(args.scratch, "kuka_table.html")
    done = subprocess.run([args.mm_plan, os.path.join(args.scenes, "kuka_table.xml"), "--seed", "1",
                           "--html", arm_page], capture_output=True, text=True, timeout=300)
    checks.check("ompl_mm_plan --html writes the KUKA TABLE page", done.returncode == 0 and os.path.isfile(arm_page),
                 done.stderr)
    size = os.path.getsize(arm_page) if os.path.isfile(arm_page) else 0
    checks.check(f"the KUKA TABLE page is under 2 MB ({size} bytes)", 0 < size < MAX_PAGE_BYTES)
    check_page(checks, "KUKA TABLE", arm_page, r"(transit|pickup cyl\d|transfer cyl\d) — [\d.]+ s of [\d.]+ s$", blank)

    cabinet_page = os.path.join(args.scratch, "kuka_cabinet.html")
    done = subprocess.run([args.mm_plan, os.path.join(args.scenes, "kuka_cabinet.xml"), "--seed", "1",
                           "--html", cabinet_page], capture_output=True, text=True, timeout=300)
    checks.check("ompl_mm_plan --html writes the KUKA CABINET page",
                 done.returncode == 0 and os.path.isfile(cabinet_page), done.stderr)
    check_page(checks, "KUKA CABINET", cabinet_page,
               r"(transit|push cyl\d|pickup cyl\d|transfer cyl\d) — [\d.]+ s of [\d.]+ s$", blank)

    # a real robot's visual meshes: the page stays small and draws them
    panda_scene = os.path.join(args.scratch, "panda_pick.xml")
    with open(panda_scene, "w") as f:
        f.write(PANDA_SCENE.format(robots=os.path.join(os.path.abspath(args.scenes), "robots", "panda", "franka_panda")))
    panda_page = os.path.join(args.scratch, "panda_pick.html")
    done = subprocess.run([args.mm_plan, panda_scene, "--seed", "1", "--html", panda_page], capture_output=True,
                          text=True, timeout=300)
    checks.check("ompl_mm_plan --html writes the Franka Panda page with no warning",
                 done.returncode == 0 and os.path.isfile(panda_page) and "Warning" not in done.stderr, done.stderr)
    size = os.path.getsize(panda_page) if os.path.isfile(panda_page) else 0
    checks.check(f"the Franka Panda page is under 3 MB ({size} bytes)", 0 < size < MAX_PANDA_PAGE_BYTES)
    check_page(checks, "Franka Panda", panda_page, r"(transit|pickup cyl1|transfer cyl1) — [\d.]+ s of [\d.]+ s$", blank)

    phys_page = os.path.join(args.scratch, "scene2.html")
    done = subprocess.run([args.phys_plan, os.path.join(args.scenes, "physics", "scene2.xml"), "--planner",
                           "sycloprrt", "--seed", "3", "--time-limit", "60", "--html", phys_page],
                          capture_output=True, text=True, timeout=300)
    checks.check("ompl_phys_plan --html writes the page", done.returncode == 0 and os.path.isfile(phys_page),
                 done.stderr)
    check_page(checks, "physics scene 2", phys_page, r"(transit|push [\w, ]+) — [\d.]+ s of [\d.]+ s$", blank)

    # without three.js the apps stop before planning, naming what is missing
    for app, scene in [(args.mm_plan, os.path.join(args.scenes, "mobile_blocked.xml")),
                       (args.phys_plan, os.path.join(args.scenes, "physics", "scene2.xml"))]:
        missing = os.path.join(args.scratch, "no_three")
        os.makedirs(missing, exist_ok=True)
        done = subprocess.run([app, scene, "--html", os.path.join(args.scratch, "never.html")], capture_output=True,
                              text=True, timeout=60, env=dict(os.environ, OMPL_MM_THREE_JS_DIR=missing))
        checks.check(f"{os.path.basename(app)} --html without three.js: exit 2 naming three.min.js and libjs-three",
                     done.returncode == 2 and "three.min.js not found" in done.stderr and "libjs-three" in done.stderr
                     and "solved" not in done.stdout, f"exit {done.returncode}", done.stdout, done.stderr)

    # the check can fail: a page that warns is caught
    with open(mm_page) as f:
        text = f.read()
    warning_page = os.path.join(args.scratch, "warns.html")
    with open(warning_page, "w") as f:
        f.write(text.replace("</body>", "<script>console.warn('planted warning');</script></body>"))
    _, problems, _ = page_state(warning_page, "paused")
    checks.check("a planted console warning is reported", "warning: planted warning" in problems, problems)

    print(f"{checks.passed} passed, {checks.failed} failed")
    return 1 if checks.failed else 0


if __name__ == "__main__":
    sys.exit(main())
