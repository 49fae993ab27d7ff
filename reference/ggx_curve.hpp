// ggx_curve.hpp - a closed curve on the unit sphere, the edge of a pdf's support (internal helper
// of the bin probabilities). It is stored as fine samples plus the points where its azimuth or its
// height turns, so both are monotone between consecutive points; crossings with a meridian or a
// latitude are then found exactly by bisection.
#pragma once

#include <functional>
#include <vector>

#include "ggx_vec.hpp"

namespace ggxref::detail {

class SphereCurve {
  public:
    // at(psi) for psi in [0, 2 pi) traces the closed curve once.
    explicit SphereCurve(std::function<Vec3(double)> at, int samples = 2048);

    // Segments whose end points' box meets z in [z0, z1], phi in [phi0, phi1] (phi in [0, 2 pi)).
    std::vector<int> segments_in(double z0, double z1, double phi0, double phi1) const;
    // On those segments: azimuths in [0, 2 pi) where the curve is tangent to a meridian,
    std::vector<double> turning_azimuths(const std::vector<int>& segments) const;
    // azimuths in [0, 2 pi) where it crosses the latitude z,
    std::vector<double> latitude_crossings(const std::vector<int>& segments, double z) const;
    // and polar angles where it crosses the half meridian of azimuth phi.
    std::vector<double> meridian_crossings(const std::vector<int>& segments, double phi) const;

  private:
    struct Point {
        double psi, z, phi, theta;
        bool turns;  // a turning point of the azimuth
    };
    Point point(double psi) const;
    template <class G> Point bisect(Point a, Point b, const G& g) const;        // g changes sign between a and b
    template <class G> Point golden_max(double a, double b, const G& g) const;  // maximum of unimodal g on [a, b]
    void add_turns(int samples);

    std::function<Vec3(double)> at_;
    std::vector<Point> pts_;  // by psi; segment k joins pts_[k] and pts_[k + 1], the last one wraps
};

}  // namespace ggxref::detail
