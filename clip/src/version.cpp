// Placeholder translation unit until the clipping pipeline lands; see clip/README.md.
namespace edgeland::clip_detail {
int clip_library_version() { return 1; }
}  // namespace edgeland::clip_detail
