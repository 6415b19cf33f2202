// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "pose_graph.hpp"

#include <cmath>
#include <numeric>

#include <Eigen/SparseCholesky>

#include "../geometry/rotation.hpp"
#include "../support/error.hpp"

namespace tripose {

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

//! The pose moved by the left update (w, v): R' = exp(w) R, t' = exp(w) t + v.
CameraPose updated(const CameraPose& pose, const Vector6d& step)
{
    const Eigen::Matrix3d turn = rotationFromVector(step.head<3>());
    CameraPose out;
    out.R = turn * pose.R;
    out.t = turn * pose.t + step.tail<3>();
    return out;
}

//! The edge's weighted error at poses @p from and @p to.
Vector6d edgeError(const PoseGraphEdge& edge, const CameraPose& from, const CameraPose& to, double translationScale)
{
    const Eigen::Matrix3d R = to.R * from.R.transpose();
    const Eigen::Vector3d t = to.t - R * from.t;
    Vector6d e;
    e.head<3>() = rotationVector(edge.relative.R.transpose() * R);
    e.tail<3>() = edge.relative.R.transpose() * (t - edge.relative.t) / translationScale;
    return std::sqrt(edge.weight) * e;
}

double totalCost(const std::vector<CameraPose>& poses, const std::vector<PoseGraphEdge>& edges, double scale)
{
    double cost = 0;
    for (const PoseGraphEdge& edge : edges)
        cost += edgeError(edge, poses[edge.from], poses[edge.to], scale).squaredNorm();
    return cost;
}

void checkGraph(const std::vector<CameraPose>& poses, const std::vector<bool>& held,
                const std::vector<PoseGraphEdge>& edges, double translationScale)
{
    if (held.size() != poses.size())
        fail(ErrorCode::BadSize, "held: %zu flags for %zu poses", held.size(), poses.size());
    if (!(std::isfinite(translationScale) && translationScale > 0))
        fail(ErrorCode::BadArgument, "translationScale: must be positive and finite, got %g", translationScale);
    const int n = (int)poses.size();
    for (int p = 0; p < n; ++p)
        if (!poses[p].allFinite())
            fail(ErrorCode::BadArgument, "poses[%d]: not finite", p);
    // Union-find over the edges: every component must hold a pose, else its place is arbitrary.
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int p) {
        while (parent[p] != p)
            p = parent[p] = parent[parent[p]];
        return p;
    };
    for (size_t i = 0; i < edges.size(); ++i)
    {
        const PoseGraphEdge& e = edges[i];
        if (e.from < 0 || e.from >= n || e.to < 0 || e.to >= n)
            fail(ErrorCode::BadArgument, "edges[%zu]: poses %d and %d, expected in [0, %d)", i, e.from, e.to, n);
        if (e.from == e.to)
            fail(ErrorCode::BadArgument, "edges[%zu]: joins pose %d to itself", i, e.from);
        if (!(std::isfinite(e.weight) && e.weight > 0))
            fail(ErrorCode::BadArgument, "edges[%zu].weight: must be positive and finite, got %g", i, e.weight);
        if (!e.relative.allFinite())
            fail(ErrorCode::BadArgument, "edges[%zu].relative: not finite", i);
        parent[root(e.from)] = root(e.to);
    }
    std::vector<bool> anchored(n, false);
    for (int p = 0; p < n; ++p)
        if (held[p])
            anchored[root(p)] = true;
    for (int p = 0; p < n; ++p)
        if (!held[p] && !anchored[root(p)])
            fail(ErrorCode::BadArgument, "edges: pose %d is linked to no held pose", p);
}

} // namespace

double optimizePoseGraph(std::vector<CameraPose>& poses, const std::vector<bool>& held,
                         const std::vector<PoseGraphEdge>& edges, double translationScale, int maxIterations)
{
    checkGraph(poses, held, edges, translationScale);
    // Each free pose has six unknowns, in pose order.
    std::vector<int> column(poses.size(), -1);
    int unknowns = 0;
    for (size_t p = 0; p < poses.size(); ++p)
        if (!held[p])
        {
            column[p] = unknowns;
            unknowns += 6;
        }
    double cost = totalCost(poses, edges, translationScale);
    if (unknowns == 0 || edges.empty())
        return cost;

    const double h = 1e-7; // central differences of the error in the update
    double damping = 1e-4;
    for (int iteration = 0; iteration < maxIterations; ++iteration)
    {
        std::vector<Eigen::Triplet<double>> entries;
        Eigen::VectorXd gradient = Eigen::VectorXd::Zero(unknowns);
        for (const PoseGraphEdge& edge : edges)
        {
            const int ends[2] = { edge.from, edge.to };
            const Vector6d e = edgeError(edge, poses[edge.from], poses[edge.to], translationScale);
            Eigen::Matrix<double, 6, 12> J = Eigen::Matrix<double, 6, 12>::Zero();
            for (int side = 0; side < 2; ++side)
            {
                if (column[ends[side]] < 0)
                    continue;
                for (int k = 0; k < 6; ++k)
                {
                    Vector6d step = Vector6d::Zero();
                    step[k] = h;
                    CameraPose plus[2] = { poses[edge.from], poses[edge.to] };
                    CameraPose minus[2] = { poses[edge.from], poses[edge.to] };
                    plus[side] = updated(plus[side], step);
                    minus[side] = updated(minus[side], -step);
                    J.col(6 * side + k) = (edgeError(edge, plus[0], plus[1], translationScale) -
                                           edgeError(edge, minus[0], minus[1], translationScale)) /
                                          (2 * h);
                }
            }
            for (int a = 0; a < 2; ++a)
            {
                const int ca = column[ends[a]];
                if (ca < 0)
                    continue;
                gradient.segment<6>(ca) += J.middleCols<6>(6 * a).transpose() * e;
                for (int b = 0; b < 2; ++b)
                {
                    const int cb = column[ends[b]];
                    if (cb < 0)
                        continue;
                    const Matrix6d block = J.middleCols<6>(6 * a).transpose() * J.middleCols<6>(6 * b);
                    for (int r = 0; r < 6; ++r)
                        for (int c = 0; c < 6; ++c)
                            entries.emplace_back(ca + r, cb + c, block(r, c));
                }
            }
        }
        Eigen::SparseMatrix<double> normal(unknowns, unknowns);
        normal.setFromTriplets(entries.begin(), entries.end());
        const Eigen::VectorXd diagonal = normal.diagonal();
        bool improved = false;
        for (int attempt = 0; attempt < 10 && !improved; ++attempt)
        {
            Eigen::SparseMatrix<double> damped = normal;
            for (int i = 0; i < unknowns; ++i)
                damped.coeffRef(i, i) += damping * (diagonal[i] + 1e-12);
            Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(damped);
            if (solver.info() != Eigen::Success)
            {
                damping *= 10;
                continue;
            }
            const Eigen::VectorXd step = solver.solve(-gradient);
            std::vector<CameraPose> trial = poses;
            for (size_t p = 0; p < poses.size(); ++p)
                if (column[p] >= 0)
                    trial[p] = updated(poses[p], step.segment<6>(column[p]));
            const double trialCost = totalCost(trial, edges, translationScale);
            if (std::isfinite(trialCost) && trialCost < cost)
            {
                const double gain = cost - trialCost;
                poses = trial;
                cost = trialCost;
                damping = std::max(1e-9, damping / 10);
                improved = true;
                if (gain <= 1e-14 * (1 + cost) || step.lpNorm<Eigen::Infinity>() < 1e-12)
                    return cost;
            }
            else
                damping *= 10;
        }
        if (!improved)
            break;
    }
    return cost;
}

} // namespace tripose
