# Type hints of the pytest plugin (the implementation is pytest_plugin.py).
import os
from typing import Any, Optional, Union

import numpy.typing as npt
import pytest

class ImageCheck:
    def baseline_dir(self) -> str: ...
    # image: linear float32/float64, or sRGB uint8/uint16 (straight alpha), an image file, a .toml spec.
    # A failure keeps actual, expected, diff and triptych images in <results>/<node id>/.
    def check(self, image: Union[npt.ArrayLike, str, os.PathLike[str]], name: Optional[str] = ...,
              **options: Any) -> dict[str, Any]: ...

def splinefig_image(request: pytest.FixtureRequest) -> ImageCheck: ...
