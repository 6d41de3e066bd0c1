// Placeholder translation unit; replaced as the resample library grows.
namespace splinefig { [[maybe_unused]] static int resample_placeholder = 0; }
