// Placeholder translation unit; replaced as the renderer library grows.
namespace splinefig { [[maybe_unused]] static int renderer_placeholder = 0; }
