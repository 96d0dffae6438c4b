#!/usr/bin/env python3
"""Every report on a phone (issues 29 and 54): Debian's chromium through chromedriver, 390 x 844
CSS pixels. A page laid out wider than the screen (the reports were 980 px wide, shown at 40 %)
fails: the document's width must not exceed the window's, tables scroll in their own box and
maps scale down. Then what a reader meets, checked mechanically (tests/phone_checks.js): a word
or number split across two lines, text under 12 px as drawn, text cut off at its box's edge or
the screen's, and chart labels over one another. A screenshot of each is kept as
SHOTS/NAME-390.png.

Usage: report_phone_test.py SHOTS NAME=REPORT.html...   (exit 1 on any failure)
"""
import os
import shutil
import sys
import tempfile

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

shots = sys.argv[1]
checks = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "phone_checks.js")).read()
pages = [a.split("=", 1) for a in sys.argv[2:]]
work = tempfile.mkdtemp()
options = webdriver.ChromeOptions()
options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
             "--user-data-dir=" + os.path.join(work, "profile")):
    options.add_argument(flag)
# A phone's viewport: 390 CSS pixels wide at a device pixel ratio of 3.
options.add_experimental_option("mobileEmulation", {
    "deviceMetrics": {"width": 390, "height": 844, "pixelRatio": 3.0}})
driver = webdriver.Chrome(service=Service(shutil.which("chromedriver") or "/usr/bin/chromedriver"),
                          options=options)
fails = 0
try:
    for name, page in pages:
        driver.get("file://" + os.path.abspath(page))
        inner = driver.execute_script("return window.innerWidth")
        doc = driver.execute_script("return document.documentElement.scrollWidth")
        shot = os.path.join(shots, name + "-390.png")
        driver.save_screenshot(shot)
        if inner != 390 or doc > inner:
            fails += 1
            print("FAIL %s at 390 px: the window is %s px and the page %s px wide" % (name, inner, doc))
            continue
        found = driver.execute_script(checks)
        if found:
            fails += 1
            print("FAIL %s at 390 px: %d problem(s) a reader meets; %s" % (name, len(found), shot))
            for f in found[:12]:
                print("     " + f)
        else:
            print("ok   %s at 390 px: the page fits (%s px), no split word, no text under 12 px, "
                  "nothing cut off or overlapping; %s" % (name, doc, shot))
finally:
    driver.quit()
    shutil.rmtree(work, ignore_errors=True)
sys.exit(1 if fails else 0)
