#!/usr/bin/env python3
"""Opens a page in headless Chromium through chromedriver's W3C endpoint, waits until
its title ends in '· ready' or holds '· error:', then saves a screenshot.
usage: tools/web_drive.py URL OUT.png [timeout_s] [extra chromium flags...]"""
import base64, json, os, subprocess, sys, time, urllib.request

url, out = sys.argv[1], sys.argv[2]
timeout = float(sys.argv[3]) if len(sys.argv) > 3 else 120
flags = sys.argv[4:] or ["--enable-unsafe-webgpu", "--enable-features=Vulkan",
                         "--use-vulkan=swiftshader", "--use-angle=swiftshader"]
port = 9515
driver = subprocess.Popen(["chromedriver", f"--port={port}"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
def call(method, path, body=None):
    req = urllib.request.Request(f"http://127.0.0.1:{port}{path}", method=method,
        data=None if body is None else json.dumps(body).encode(), headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(req, timeout=60) as r:
        return json.load(r)["value"]
title = ""
try:
    for _ in range(50):
        try:
            call("GET", "/status"); break
        except Exception:
            time.sleep(0.1)
    caps = {"capabilities": {"alwaysMatch": {"browserName": "chrome", "goog:loggingPrefs": {"browser": "ALL"}, "goog:chromeOptions": {
        "binary": "/usr/bin/chromium",
        "args": ["--headless=new", "--no-sandbox", "--window-size=1280,800"] + flags}}}}
    session = call("POST", "/session", caps)["sessionId"]
    call("POST", f"/session/{session}/url", {"url": url})
    start = time.time(); title = ""
    while time.time() - start < timeout:
        title = call("GET", f"/session/{session}/title")
        if title.endswith("· ready") or "· error:" in title:
            break
        time.sleep(0.5)
    print(f"title after {time.time() - start:.1f} s: {title!r}")
    # Seconds more for what comes after the first frame (the numbers of a view at rest).
    time.sleep(float(os.environ.get("WEB_DRIVE_SETTLE", "0")))
    png = base64.b64decode(call("GET", f"/session/{session}/screenshot"))
    open(out, "wb").write(png)
    message = call("POST", f"/session/{session}/execute/sync", {"script": "return document.getElementById('message') ? document.getElementById('message').textContent : ''", "args": []})
    print("message:", message)
    try:
        for entry in call("POST", f"/session/{session}/se/log", {"type": "browser"})[-15:]:
            print("console:", entry.get("level"), entry.get("message")[:400])
    except Exception as e:
        print("no console log:", e)
    call("DELETE", f"/session/{session}")
finally:
    driver.kill()
# A driver that can fail: not ready in time, or an error in the title, is exit 1.
sys.exit(0 if title.endswith("· ready") else 1)
