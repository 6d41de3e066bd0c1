// Placeholder translation unit; replaced as the compare library grows.
namespace splinefig { [[maybe_unused]] static int compare_placeholder = 0; }
