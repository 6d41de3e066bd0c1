# Type hints of the pytest plugin (the implementation is pytest_plugin.py).
from typing import Any, Optional

import pytest

class ImageCheck:
    def baseline_dir(self) -> str: ...
    def check(self, image: Any, name: Optional[str] = ..., **options: Any) -> dict[str, Any]: ...

def splinefig_image(request: pytest.FixtureRequest) -> ImageCheck: ...
