"""render_spec applies the command line's rules to the spec it reads by name: a regular file,
at most 64 MiB, no NUL in the path. /dev/zero grew without bound, a FIFO blocked and a
directory gave a blank image."""
import os

import pytest

import splinefig


@pytest.mark.parametrize(
    "path, says",
    [
        ("/dev/zero", "/dev/zero: not a regular file (a FIFO, socket or device)"),
        ("/dev/urandom", "/dev/urandom: not a regular file (a FIFO, socket or device)"),
        ("/", "/: is a directory, not a file"),
        ("a\0b.toml", "spec: a path holding a NUL character"),
        ("/no/such/spec.toml", "/no/such/spec.toml: cannot read the spec file (No such file or directory)"),
    ],
)
def test_render_spec_refuses_what_is_not_a_spec_file(path, says):
    with pytest.raises(ValueError) as e:
        splinefig.render_spec(path)
    assert str(e.value) == says


def test_render_spec_refuses_a_fifo_without_blocking(tmp_path):
    fifo = tmp_path / "spec.toml"
    os.mkfifo(fifo)
    with pytest.raises(ValueError) as e:
        splinefig.render_spec(str(fifo))
    assert str(e.value).endswith("spec.toml: not a regular file (a FIFO, socket or device)")


def test_no_function_takes_a_path_holding_a_nul(tmp_path):
    image = splinefig.image_buffer(2, 2, 4)
    with pytest.raises(ValueError, match="path: a path holding a NUL character"):
        splinefig.write_image(str(tmp_path / "a\0b.png"), image)
    with pytest.raises(ValueError, match="path: a path holding a NUL character"):
        splinefig.read_image(str(tmp_path / "a\0b.png"))
    # A built-in figure's name becomes a path too; the name is not echoed with its NUL.
    with pytest.raises(ValueError) as e:
        splinefig.render_figure("bi\0as")
    assert str(e.value) == "name: a name holding a NUL character"
    assert list(tmp_path.iterdir()) == []
