// pdf_bins.cpp - the bins' probabilities under a device pdf, integrated adaptively.
#include "pdf_bins.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <boost/math/quadrature/gauss.hpp>

#include "reference_bridge.hpp"

namespace ggxbridge {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr int rule_points = 8;                          // per axis, per region
constexpr int max_depth = 12, max_rounds = 16;

// The nodes and weights of the N-point Gauss-Legendre rule on [0, 1].
struct UnitRule {
    std::vector<double> nodes, weights;
};

UnitRule unit_rule()
{
    using rule = boost::math::quadrature::gauss<double, rule_points>;
    UnitRule r;
    for (std::size_t k = 0; k < rule::abscissa().size(); ++k)
        for (double sign : {-1.0, 1.0}) {
            r.nodes.push_back(0.5 + 0.5 * sign * rule::abscissa()[k]);
            r.weights.push_back(0.5 * rule::weights()[k]);
        }
    return r;
}

struct Estimate {
    double kept = 0.0, whole = 0.0;
};

// A rectangle of (cos theta, phi) inside one bin, its own rule's estimate and its quarters'.
struct Region {
    double z0, z1, p0, p1;
    int bin, depth;
    Estimate own, quarters[4];

    Region quarter(int k) const
    {
        const double zm = 0.5 * (z0 + z1), pm = 0.5 * (p0 + p1);
        Region r{k & 1 ? zm : z0, k & 1 ? z1 : zm, k & 2 ? pm : p0, k & 2 ? p1 : pm, bin, depth + 1, quarters[k], {}};
        return r;
    }
    Estimate fine() const
    {
        Estimate e;
        for (const Estimate& q : quarters) {
            e.kept += q.kept;
            e.whole += q.whole;
        }
        return e;
    }
    double error() const
    {
        const Estimate f = fine();
        return std::max(std::fabs(f.kept - own.kept), std::fabs(f.whole - own.whole));
    }
    double area() const { return (z1 - z0) * (p1 - p0); }
};

// Evaluates the rule on rectangles: each node's direction, one pdf call, the weighted sums.
class RuleEvaluator {
public:
    RuleEvaluator(const DirectionPdf& pdf, const ggxcl::SampleParams& params, ggxcl::Field direction)
        : pdf_(pdf), params_(params), of_m_(direction == ggxcl::Field::m), rule_(unit_rule())
    {
        const ggxcl::Vec3 v = ggxcl::normalized(params).view;
        i_[0] = v.x;
        i_[1] = v.y;
        i_[2] = v.z;
    }

    // The estimate of each rectangle {z0, z1, p0, p1}.
    std::vector<Estimate> run(const std::vector<std::array<double, 4>>& rects)
    {
        std::vector<ggxcl::Vec3> dirs;
        std::vector<double> factor;  // 4 |i.m| for m (0 where m.z <= 0), 1 for o
        std::vector<char> kept;      // o above the horizon
        dirs.reserve(rects.size() * nodes());
        for (const auto& r : rects)
            for (double nz : rule_.nodes)
                for (double np : rule_.nodes)
                    add_node(r[0] + nz * (r[1] - r[0]), r[2] + np * (r[3] - r[2]), dirs, factor, kept);
        const std::vector<float> values = pdf_(params_, dirs);
        evaluations_ += dirs.size();
        std::vector<Estimate> out(rects.size());
        std::size_t k = 0;
        for (std::size_t j = 0; j < rects.size(); ++j) {
            const double area = (rects[j][1] - rects[j][0]) * (rects[j][3] - rects[j][2]);
            for (double wz : rule_.weights)
                for (double wp : rule_.weights) {
                    const double f = factor[k] == 0.0 ? 0.0 : double(values[k]) * factor[k] * wz * wp * area;
                    out[j].whole += f;
                    out[j].kept += kept[k] ? f : 0.0;
                    ++k;
                }
        }
        return out;
    }
    std::size_t evaluations() const { return evaluations_; }
    static std::size_t nodes() { return std::size_t(rule_points) * rule_points; }

private:
    void add_node(double z, double phi, std::vector<ggxcl::Vec3>& dirs, std::vector<double>& factor,
                  std::vector<char>& kept) const
    {
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        double d[3] = {r * std::cos(phi), r * std::sin(phi), z};
        double f = 1.0;
        if (of_m_) {
            const double im = i_[0] * d[0] + i_[1] * d[1] + i_[2] * d[2];
            f = d[2] > 0.0 ? 4.0 * std::fabs(im) : 0.0;
            for (int a = 0; a < 3; ++a)
                d[a] = 2.0 * im * d[a] - i_[a];  // o = reflect(i, m)
        }
        dirs.push_back({float(d[0]), float(d[1]), float(d[2])});
        factor.push_back(f);
        kept.push_back(d[2] > 0.0);
    }

    const DirectionPdf& pdf_;
    const ggxcl::SampleParams& params_;
    bool of_m_;
    UnitRule rule_;
    double i_[3];
    std::size_t evaluations_ = 0;
};

// Own and quarter estimates of regions whose rectangles are set.
void estimate(RuleEvaluator& rule, std::vector<Region>& regions, bool own_too)
{
    std::vector<std::array<double, 4>> rects;
    for (const Region& r : regions) {
        if (own_too)
            rects.push_back({r.z0, r.z1, r.p0, r.p1});
        for (int k = 0; k < 4; ++k) {
            const Region q = r.quarter(k);
            rects.push_back({q.z0, q.z1, q.p0, q.p1});
        }
    }
    const std::vector<Estimate> e = rule.run(rects);
    std::size_t at = 0;
    for (Region& r : regions) {
        if (own_too)
            r.own = e[at++];
        for (Estimate& q : r.quarters)
            q = e[at++];
    }
}

// Each bin's error target: a tenth of its count's Poisson noise, and 1e-4 of its probability (at
// least 1e-5 of a uniform bin's), so that the whole stays within about 2e-4.
std::vector<double> bin_targets(const std::vector<Region>& leaves, std::size_t bins, std::uint64_t samples)
{
    std::vector<double> whole(bins, 0.0);
    for (const Region& r : leaves)
        whole[std::size_t(r.bin)] += std::fabs(r.fine().whole);
    const double n = double(std::max<std::uint64_t>(samples, 1));
    std::vector<double> target(bins);
    for (std::size_t b = 0; b < bins; ++b)
        target[b] = std::min(0.1 * std::sqrt(std::max(whole[b], 1.0 / n) / n),
                             std::max(1e-4 * whole[b], 1e-5 / double(bins)));
    return target;
}

// The leaves to quarter this round, worst first, within the remaining budget.
std::vector<std::size_t> leaves_to_refine(const std::vector<Region>& leaves, const BinRequest& request,
                                          const std::vector<double>& bin_area, std::size_t budget)
{
    const std::size_t bins = bin_area.size();
    const std::vector<double> target = bin_targets(leaves, bins, request.samples);
    std::vector<double> found(bins, 0.0);
    for (const Region& r : leaves)
        found[std::size_t(r.bin)] += std::fabs(r.fine().whole) + std::fabs(r.own.whole);
    std::vector<std::pair<double, std::size_t>> picks;  // (error over target, leaf)
    for (std::size_t k = 0; k < leaves.size(); ++k) {
        const Region& r = leaves[k];
        if (r.depth >= max_depth)
            continue;
        const double share = target[std::size_t(r.bin)] * r.area() / bin_area[std::size_t(r.bin)];
        const bool unexplained = request.observed && (*request.observed)[std::size_t(r.bin)] > 0 &&
                                 found[std::size_t(r.bin)] == 0.0 && r.depth < 6;
        if (unexplained)
            picks.push_back({1e300, k});
        else if (r.error() > share)  // false for NaN: a pdf that is not finite is not chased
            picks.push_back({r.error() / share, k});
    }
    std::sort(picks.begin(), picks.end(), std::greater<>());
    const std::size_t per_leaf = 16 * RuleEvaluator::nodes();
    std::vector<std::size_t> out;
    for (const auto& [ratio, k] : picks) {
        if ((out.size() + 1) * per_leaf > budget)
            break;
        out.push_back(k);
    }
    return out;
}

// Each bin's integral by one rule over it (no refinement, no error estimate).
BinIntegrals one_pass(RuleEvaluator& rule, const std::vector<Region>& bins, std::size_t count)
{
    std::vector<std::array<double, 4>> rects;
    for (const Region& r : bins)
        rects.push_back({r.z0, r.z1, r.p0, r.p1});
    const std::vector<Estimate> e = rule.run(rects);
    BinIntegrals out{std::vector<double>(count, 0.0), std::vector<double>(count, 0.0), std::vector<double>(count, 0.0),
                     rule.evaluations(), 0};
    for (std::size_t k = 0; k < bins.size(); ++k) {
        out.kept[std::size_t(bins[k].bin)] += e[k].kept;
        out.whole[std::size_t(bins[k].bin)] += e[k].whole;
    }
    return out;
}

// A bin whose samples found no density at any node, however fine (a support thinner than the
// finest subdivision, as near a view opposite the normal): its samples' share is its error, so
// that the integral's error bar says what the quadrature could not see.
void add_unexplained_mass(BinIntegrals& out, const BinRequest& request)
{
    if (!request.observed)
        return;
    double n = 0.0;
    for (std::uint64_t c : *request.observed)
        n += double(c);
    for (std::size_t b = 0; b < out.whole.size() && n > 0.0; ++b)
        if (out.whole[b] == 0.0 && (*request.observed)[b] > 0)
            out.error[b] += double((*request.observed)[b]) / n;
}

// The bins' edges in cos theta: the request's own, or bins_z equal steps over [-1, 1].
std::vector<double> z_edges_of(const BinRequest& request)
{
    if (!request.z_edges.empty())
        return request.z_edges;
    std::vector<double> edges;
    for (int zb = 0; zb <= request.bins_z; ++zb)
        edges.push_back(-1.0 + 2.0 * zb / request.bins_z);
    return edges;
}

} // namespace

double BinIntegrals::kept_total() const { return std::accumulate(kept.begin(), kept.end(), 0.0); }
double BinIntegrals::whole_total() const { return std::accumulate(whole.begin(), whole.end(), 0.0); }
double BinIntegrals::error_total() const { return std::accumulate(error.begin(), error.end(), 0.0); }

BinIntegrals integrate_bins(const DirectionPdf& pdf, const ggxcl::SampleParams& params, const BinRequest& request)
{
    RuleEvaluator rule(pdf, params, request.direction);
    const std::vector<double> edges = z_edges_of(request);
    const int bins_z = int(edges.size()) - 1;
    const double dphi = 2.0 * pi / request.bins_phi;
    std::vector<Region> leaves;
    std::vector<double> bin_area;
    for (int zb = 0; zb < bins_z; ++zb)
        for (int pb = 0; pb < request.bins_phi; ++pb) {
            leaves.push_back({edges[std::size_t(zb)], edges[std::size_t(zb) + 1], pb * dphi, (pb + 1) * dphi,
                              zb * request.bins_phi + pb, 0, {}, {}});
            bin_area.push_back(leaves.back().area());
        }
    if (request.refinement_budget == 0) {  // one rule per bin, no error estimate
        return one_pass(rule, leaves, bin_area.size());
    }
    estimate(rule, leaves, true);
    const std::size_t initial = rule.evaluations();
    int deepest = 0;
    for (int round = 0; round < max_rounds; ++round) {
        const std::size_t used = rule.evaluations() - initial;
        const std::size_t budget = used < request.refinement_budget ? request.refinement_budget - used : 0;
        const std::vector<std::size_t> refine = leaves_to_refine(leaves, request, bin_area, budget);
        if (refine.empty())
            break;
        std::vector<Region> children;
        std::vector<char> replaced(leaves.size(), 0);
        for (std::size_t k : refine) {
            replaced[k] = 1;
            for (int q = 0; q < 4; ++q)
                children.push_back(leaves[k].quarter(q));
        }
        estimate(rule, children, false);
        std::vector<Region> next;
        for (std::size_t k = 0; k < leaves.size(); ++k)
            if (!replaced[k])
                next.push_back(leaves[k]);
        for (const Region& c : children) {
            deepest = std::max(deepest, c.depth);
            next.push_back(c);
        }
        leaves.swap(next);
    }
    const std::size_t bins = bin_area.size();
    BinIntegrals out{std::vector<double>(bins, 0.0), std::vector<double>(bins, 0.0), std::vector<double>(bins, 0.0),
                     rule.evaluations(), deepest};
    for (const Region& r : leaves) {
        const Estimate f = r.fine();
        out.kept[std::size_t(r.bin)] += f.kept;
        out.whole[std::size_t(r.bin)] += f.whole;
        out.error[std::size_t(r.bin)] += r.error();
    }
    add_unexplained_mass(out, request);
    return out;
}

DirectionPdf direction_pdf(ggxcl::Backend& backend)
{
    return [&backend](const ggxcl::SampleParams& p, const std::vector<ggxcl::Vec3>& o) { return backend.pdf(p, o); };
}

DirectionPdf reference_direction_pdf(ggxcl::Method method)
{
    return [method](const ggxcl::SampleParams& p, const std::vector<ggxcl::Vec3>& directions) {
        ggxcl::SampleParams theirs = ggxcl::normalized(p);
        theirs.method = method;
        theirs.user_sampler = nullptr;
        const ggxref::Params ref = reference_params(theirs);
        std::vector<float> out(directions.size());
        for (std::size_t k = 0; k < directions.size(); ++k) {
            const ggxcl::Vec3& o = directions[k];
            const double len = std::sqrt(double(o.x) * o.x + double(o.y) * o.y + double(o.z) * o.z);
            out[k] = float(ggxref::pdf_o(reference_method(method), ref, {o.x / len, o.y / len, o.z / len}));
        }
        return out;
    };
}

bool claimed_method(ggxcl::Distribution distribution, ggxcl::Method& method)
{
    if (distribution == ggxcl::Distribution::own)
        return false;
    method = distribution == ggxcl::Distribution::vndf ? ggxcl::Method::heitz : ggxcl::Method::ndf;
    return true;
}

std::vector<double> claimed_bin_probabilities(const ggxcl::SampleParams& params, int bins_z, int bins_phi)
{
    ggxcl::SampleParams theirs = ggxcl::normalized(params);
    if (!claimed_method(params.user_sampler->distribution(), theirs.method))
        return {};
    theirs.user_sampler = nullptr;
    return bin_probabilities(theirs.method, theirs, bins_z, bins_phi, ggxcl::Field::o);
}

ClaimedBins claimed_bins(const ggxcl::SampleParams& params, ggxcl::Method claimed, const BinRequest& request,
                         const std::vector<double>& whole)
{
    ClaimedBins out;
    if (request.direction == ggxcl::Field::m) {
        const BinIntegrals m =
            integrate_bins(reference_direction_pdf(claimed), params, request);
        out.kept = m.kept;
        out.below = m.whole_total() - m.kept_total();
        return out;
    }
    out.kept = whole;
    const int upper_from = request.bins_z / 2;  // bins_z is even: the horizon is a bin edge
    for (int zb = 0; zb < upper_from; ++zb)
        for (int pb = 0; pb < request.bins_phi; ++pb) {
            double& p = out.kept[std::size_t(zb) * std::size_t(request.bins_phi) + std::size_t(pb)];
            out.below += p;
            p = 0.0;
        }
    return out;
}

UserFits user_fits(const DirectionPdf& pdf, const ggxcl::SampleParams& params, const ggxcl::Histogram& counts,
                   const BinRequest& request, const std::vector<double>& claimed_whole)
{
    UserFits fits;
    fits.own = integrate_bins(pdf, params, request);
    fits.own_fit = user_histogram_fit(counts, fits.own.kept, fits.own.error, false);
    fits.claims = claimed_method(params.user_sampler->distribution(), fits.claimed_method);
    if (fits.claims) {
        fits.claimed = claimed_bins(params, fits.claimed_method, request, claimed_whole);
        fits.claimed_fit = user_histogram_fit(counts, fits.claimed.kept, {}, true);
    }
    return fits;
}

} // namespace ggxbridge
