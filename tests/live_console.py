"""What the console tests share: where `planter-sim live` says its console is."""
import re
import sys
import time


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
