"""What the console tests share: where `planter-sim live` says its console is, and one request
to it as a phone's browser would make it."""
import json
import re
import sys
import time
import urllib.error
import urllib.request


def console_address(log_path, tries=100):
    """The console's URL and pairing secret from planter-sim live's output (written to
    log_path), waiting up to tries x 0.1 s; exits the test with the output if it never says."""
    for _ in range(tries):
        text = open(log_path).read()
        m = re.search(r"^console: (http://\S+) ", text, re.M)
        s = re.search(r"pairing secret (\S+)", text)
        if m and s:
            return m.group(1).rstrip("/"), s.group(1)
        time.sleep(0.1)
    print("FAIL planter-sim live did not start:\n" + open(log_path).read())
    sys.exit(1)


def http_call(url, path, body=None, headers=None):
    """One request to the console at url: a JSON body is POSTed, none is a GET. Returns the
    status, the body's text and the headers, for an error status too."""
    h = dict(headers or {})
    data = None
    if body is not None:
        h["Content-Type"] = "application/json"
        data = json.dumps(body).encode()
    try:
        with urllib.request.urlopen(urllib.request.Request(url + path, data=data, headers=h),
                                    timeout=10) as r:
            return r.status, r.read().decode(), r.headers
    except urllib.error.HTTPError as e:
        return e.code, e.read().decode(), e.headers
