#include "render/snow_view_block.h"

namespace grass::render {

SnowViewBlock snowViewBlock(const core::OrthoSnowView& view, int resolution) {
    SnowViewBlock block;
    block.origin = view.origin;
    block.sizeM = view.sizeM;
    block.right = view.right;
    block.depthRangeM = view.depthRangeM;
    block.upAxis = view.up;
    block.resolution = resolution;
    block.forward = view.forward;
    return block;
}

}  // namespace grass::render
