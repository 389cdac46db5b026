#include "split_point.h"

namespace cetview::brep {

void analyticSplitWeights(const cet::Point2 p[3], const bool chord[3], double b[3]) {
  double squared[3];  // edge i's length squared, opposite corner i
  for (int i = 0; i < 3; ++i) {
    const cet::Point2 a = p[(i + 1) % 3], c = p[(i + 2) % 3];
    squared[i] = (a.x - c.x) * (a.x - c.x) + (a.y - c.y) * (a.y - c.y);
  }
  // The circumcentre's barycentric weights, up to their sum: a^2 (b^2 + c^2 - a^2) and so on.
  double w[3], sum = 0;
  for (int i = 0; i < 3; ++i) sum += w[i] = squared[i] * (squared[(i + 1) % 3] + squared[(i + 2) % 3] - squared[i]);
  if (sum > 0 && w[0] > 0 && w[1] > 0 && w[2] > 0) {
    for (int i = 0; i < 3; ++i) b[i] = w[i] / sum;
    return;
  }
  const int longest = squared[0] >= squared[1] ? (squared[0] >= squared[2] ? 0 : 2) : (squared[1] >= squared[2] ? 1 : 2);
  for (int i = 0; i < 3; ++i) b[i] = chord[longest] ? 1.0 / 3 : (i == longest ? 0 : 0.5);
}

}  // namespace cetview::brep
