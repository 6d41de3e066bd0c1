"""A pytest plugin that runs matplotlib's own check_figures_equal tests with the splinefig
backend drawing every PNG (docs/matplotlib.md).

It keeps only the items whose function is check_figures_equal's wrapper with ext "png" (both
figures of such a test are saved as PNG and compared by matplotlib's compare_images), and
replaces the Agg canvas's print_png, which savefig uses for ".png", by one that draws the figure
with splinefig.matplotlib.RendererSplinefig. SPLINEFIG_CFE_BACKEND=agg keeps AGG (the
reference run); SPLINEFIG_MPL_BLEND=linear blends in linear light.
"""
import os


def _is_png_check(item) -> bool:
    fn = getattr(item, "obj", None)
    qual = getattr(fn, "__qualname__", "")
    if "check_figures_equal" not in qual or not qual.endswith("wrapper"):
        return False
    callspec = getattr(item, "callspec", None)
    return callspec is not None and callspec.params.get("ext") == "png"


def pytest_collection_modifyitems(session, config, items):
    keep = [it for it in items if _is_png_check(it)]
    drop = [it for it in items if not _is_png_check(it)]
    if drop:
        config.hook.pytest_deselected(items=drop)
    items[:] = keep


def _splinefig_print_png(self, filename_or_obj, *args, metadata=None, pil_kwargs=None, **kwargs):
    import matplotlib as mpl
    from splinefig.matplotlib import RendererSplinefig

    w, h = self.figure.bbox.size
    renderer = RendererSplinefig(w, h, self.figure.dpi)
    self.figure.draw(renderer)
    mpl.image.imsave(filename_or_obj, renderer.rgba8(), format="png", origin="upper", dpi=self.figure.dpi,
                     metadata=metadata, pil_kwargs=pil_kwargs)


def pytest_configure(config):
    if os.environ.get("SPLINEFIG_CFE_BACKEND", "splinefig") == "agg":
        return
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    FigureCanvasAgg.print_png = _splinefig_print_png


def pytest_report_header(config):
    return f"check_figures_equal PNGs drawn by: {os.environ.get('SPLINEFIG_CFE_BACKEND', 'splinefig')}"
