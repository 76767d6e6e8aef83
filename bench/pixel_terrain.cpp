#include "pixel_terrain.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace edgeland::bench {
namespace {

// Twice the signed area of a contour (x right, y up: counter-clockwise is positive).
std::int64_t twice_area(const std::vector<cv::Point>& loop) {
  std::int64_t sum = 0;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
    sum += std::int64_t{loop[j].x} * loop[i].y - std::int64_t{loop[i].x} * loop[j].y;
  return sum;
}

}  // namespace

PixelTerrain::PixelTerrain(b2World& world, const BitmapWorld& bitmap, const Options& options)
    : world_(world),
      options_(options),
      chunks_x_((bitmap.width() + kChunk - 1) / kChunk),
      chunks_y_((bitmap.height() + kChunk - 1) / kChunk),
      mask_(static_cast<int>(kChunk + 2), static_cast<int>(kChunk + 2), CV_8UC1, cv::Scalar(0)) {
  for (std::size_t m = 1; m < kMaterialCount; ++m) mask_value_[m] = options.solid[m] ? 255 : 0;
  b2BodyDef def;
  def.type = b2_staticBody;
  const std::int64_t grid = std::max<std::int64_t>(1, options.body_grid);
  bodies_.resize(static_cast<std::size_t>(grid * grid));
  for (b2Body*& body : bodies_) body = world_.CreateBody(&def);
  fixtures_.resize(static_cast<std::size_t>(chunks_x_ * chunks_y_));
  for (std::int64_t cy = 0; cy < chunks_y_; ++cy)
    for (std::int64_t cx = 0; cx < chunks_x_; ++cx)
      region_.push_back(
          static_cast<std::size_t>((cy * grid / chunks_y_) * grid + cx * grid / chunks_x_));
  for (std::int64_t cy = 0; cy < chunks_y_; ++cy) {
    traced_.assign(1, {});
    for (std::int64_t cx = 0; cx < chunks_x_; ++cx) {
      trace_chunk(bitmap, cx, cy, traced_.front());
      rebuild(traced_);
    }
  }
}

PixelTerrain::~PixelTerrain() {
  for (b2Body* body : bodies_) world_.DestroyBody(body);
}

std::size_t PixelTerrain::fixture_count() const {
  std::size_t n = 0;
  for (const auto& list : fixtures_) n += list.size();
  return n;
}

std::size_t PixelTerrain::vertex_count() const {
  std::size_t n = 0;
  for (const auto& list : fixtures_)
    for (const b2Fixture* f : list)
      n += static_cast<std::size_t>(static_cast<const b2ChainShape*>(f->GetShape())->m_count - 1);
  return n;
}

// The chunk's solid squares as a zero-padded mask (a byte lookup per square), its contours
// (two levels: outer borders and the holes in them, Suzuki-Abe as OpenCV implements it, with
// straight runs compressed), each simplified (Douglas-Peucker) and oriented with solid on its
// left; loops of fewer than 3 points (a lone square, a one-square line) are dropped.
void PixelTerrain::trace_chunk(const BitmapWorld& bitmap, std::int64_t cx, std::int64_t cy,
                               ChunkLoops& out) {
  const std::int64_t x0 = cx * kChunk, y0 = cy * kChunk;
  const std::int64_t w = std::min(kChunk, bitmap.width() - x0);
  const std::int64_t h = std::min(kChunk, bitmap.height() - y0);
  for (std::int64_t y = 0; y < kChunk; ++y) {
    std::uint8_t* line = mask_.ptr<std::uint8_t>(static_cast<int>(y + 1)) + 1;
    if (y >= h) {
      std::fill(line, line + kChunk, 0);
      continue;
    }
    const std::uint8_t* squares = bitmap.row(y0 + y) + x0;
    for (std::int64_t x = 0; x < w; ++x) line[x] = mask_value_[squares[x]];
    std::fill(line + w, line + kChunk, 0);
  }
  out.chunk = static_cast<std::size_t>(cy * chunks_x_ + cx);
  out.loops.clear();
  cv::findContours(mask_, contours_, hierarchy_, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE,
                   cv::Point(static_cast<int>(x0 - 1), static_cast<int>(y0 - 1)));
  for (std::size_t i = 0; i < contours_.size(); ++i) {
    std::vector<cv::Point> loop;
    cv::approxPolyDP(contours_[i], loop, options_.epsilon, true);
    if (loop.size() < 3) continue;
    const bool hole = hierarchy_[i][3] >= 0;
    if ((twice_area(loop) < 0) != hole) std::reverse(loop.begin(), loop.end());
    out.loops.push_back(std::move(loop));
  }
}

const std::vector<PixelTerrain::ChunkLoops>& PixelTerrain::trace(const BitmapWorld& bitmap,
                                                                 const Box64& box) {
  // The squares whose centres the box can hold: [box.min, box.max - 1] locally.
  const Box64& w = bitmap.world();
  const auto chunk_of = [](std::int64_t local, std::int64_t count) {
    return std::clamp<std::int64_t>(local < 0 ? -1 : local / kChunk, 0, count - 1);
  };
  const std::int64_t cx0 = chunk_of(box.min.x - w.min.x, chunks_x_);
  const std::int64_t cx1 = chunk_of(box.max.x - 1 - w.min.x, chunks_x_);
  const std::int64_t cy0 = chunk_of(box.min.y - w.min.y, chunks_y_);
  const std::int64_t cy1 = chunk_of(box.max.y - 1 - w.min.y, chunks_y_);
  const auto count = static_cast<std::size_t>((cx1 - cx0 + 1) * (cy1 - cy0 + 1));
  if (traced_.size() < count) traced_.resize(count);
  std::size_t k = 0;
  for (std::int64_t cy = cy0; cy <= cy1; ++cy)
    for (std::int64_t cx = cx0; cx <= cx1; ++cx) trace_chunk(bitmap, cx, cy, traced_[k++]);
  traced_.resize(count);
  return traced_;
}

void PixelTerrain::rebuild(const std::vector<ChunkLoops>& traced) {
  for (const ChunkLoops& c : traced) {
    b2Body* body = bodies_[region_[c.chunk]];
    std::vector<b2Fixture*>& list = fixtures_[c.chunk];
    for (b2Fixture* f : list) body->DestroyFixture(f);
    list.clear();
    for (const std::vector<cv::Point>& loop : c.loops) {
      vertices_.clear();
      for (const cv::Point& p : loop)
        vertices_.push_back({static_cast<float>((p.x + 0.5) / options_.units_per_metre),
                             static_cast<float>((p.y + 0.5) / options_.units_per_metre)});
      b2ChainShape shape;
      shape.CreateLoop(vertices_.data(), static_cast<int32>(vertices_.size()));
      b2FixtureDef def;
      def.shape = &shape;
      def.friction = 0.6f;
      list.push_back(body->CreateFixture(&def));
    }
  }
}

}  // namespace edgeland::bench
