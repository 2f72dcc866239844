"""What the Yade adapters share (docs/clients.md): running a Yade script and leaving nothing behind.
Python 3 stdlib only."""
import os
import shutil
import subprocess

# The first line of every script: Yade's own temporary folder, named for removal.
NAME_TMP = 'import os\nopen("yade_tmp", "w").write(os.path.dirname(O.tmpFilename()))\n'


def run_yade(script):
    """Runs `script` (which starts with NAME_TMP) in Yade, in the current directory. Yade keeps an
    IPython profile (IPYTHONDIR, else ~/.ipython): here, in the scratch directory, which rotbench
    removes. It also makes /tmp/yade-XXXXXX whatever TMPDIR says, and leaves it: the script names
    it, and it is removed here."""
    open("rotbench_yade.py", "w").write(script)
    env = dict(os.environ, IPYTHONDIR=os.path.join(os.getcwd(), "ipython"))
    try:
        subprocess.run(["yade", "-n", "-x", "rotbench_yade.py"], check=True, stdout=subprocess.DEVNULL, env=env)
    finally:
        if os.path.exists("yade_tmp"):
            folder = open("yade_tmp").read()
            if os.path.basename(folder).startswith("yade-") and os.path.isdir(folder):
                shutil.rmtree(folder)
