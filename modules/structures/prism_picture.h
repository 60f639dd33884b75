// A picture of structures.prism's model for its README and for checking it by eye: the textured
// facets drawn by OpenCV (painter's algorithm, each planar facet's texture warped by the
// homography of its uvs to the picture), from a viewpoint around the model.
#pragma once

#include <opencv2/core.hpp>

#include "content/content.h"

namespace maquette::structures {

// `model` (z up, metres) seen from `azimuth_deg` (clockwise from north, +y) and `elevation_deg`
// above the horizon by a camera of 50 degrees of horizontal field of view, framing the model's
// bounding sphere; a white background. Facets facing away are not drawn; nearer facets over
// farther ones by their centres' depths (right for a convex model). Precondition: every object is
// one planar facet with at least 3 vertices, uvs when its material has an image.
cv::Mat picture_of_model(const MeshContent& model, int width, int height, double azimuth_deg,
                         double elevation_deg);

}  // namespace maquette::structures
