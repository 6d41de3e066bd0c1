"""Spec text whose keys or values nest deeply: refused with a ValueError naming the line and the
limit before the TOML parser recurses, also on a thread with a small stack, and the interpreter
lives on (toml++ recursed once per key part and per nesting level: a 50000-part dotted key
overflowed the stack and killed the interpreter)."""
import subprocess
import sys
import textwrap

import pytest

import splinefig

DEEP_KEY = 'title = "t"\n' + ".".join(["a"] * 50000) + " = 1\n"
DEEP_HEADER = "[" + ".".join(["a"] * 1000) + "]\nb = 1\n"
DEEP_ARRAYS = "a = " + "[" * 100000 + "]" * 100000 + "\n"
DEEP_TABLES = "a = " + "{b = " * 150 + "1" + "}" * 150 + "\n"
KEY_SAYS = "a dotted key of more than 64 parts (the limit of key and table-header depth)"
NEST_SAYS = "arrays and inline tables nested more than 16 deep (the limit of value nesting)"


@pytest.mark.parametrize("text, says", [
    (DEEP_KEY, "<text>:2: " + KEY_SAYS),
    (DEEP_HEADER, "<text>:1: " + KEY_SAYS),
    (DEEP_ARRAYS, "<text>:1: " + NEST_SAYS),
    (DEEP_TABLES, "<text>:1: " + NEST_SAYS),
])
def test_deep_spec_text_is_refused(text, says):
    with pytest.raises(ValueError) as e:
        splinefig.render_spec(None, text=text)
    assert str(e.value) == says


def test_deep_spec_files_are_refused(tmp_path):
    (tmp_path / "deep.toml").write_text(DEEP_KEY)
    with pytest.raises(ValueError, match=r"deep\.toml:2: a dotted key of more than 64 parts"):
        splinefig.render_spec(str(tmp_path / "deep.toml"))


def test_limits_hold_on_a_small_thread_stack():
    # In a fresh interpreter, so that a crash fails this test instead of ending the run: every
    # deep text refused on a thread with a 256 KiB stack, and 16 levels (the limit) parsed there.
    code = textwrap.dedent("""
        import threading, splinefig
        texts = [
            'title = "t"\\n' + ".".join(["a"] * 50000) + " = 1\\n",
            "[" + ".".join(["a"] * 1000) + "]\\nb = 1\\n",
            "a = " + "[" * 100000 + "]" * 100000 + "\\n",
            "a = " + "{b = " * 150 + "1" + "}" * 150 + "\\n",
            "a = " + "[" * 16 + "]" * 16 + "\\n",
        ]
        out = []
        def work():
            for t in texts:
                try:
                    splinefig.render_spec(None, text=t)
                    out.append("drawn")
                except ValueError as e:
                    out.append(str(e)[:30])
        threading.stack_size(256 * 1024)
        th = threading.Thread(target=work)
        th.start()
        th.join()
        print("|".join(out))
    """)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().split("|") == [
        "<text>:2: a dotted key of more", "<text>:1: a dotted key of more", "<text>:1: arrays and inline ta",
        "<text>:1: arrays and inline ta", "<text>:1: a: unknown key"]
