/**
 * @file boundary_depth.cc
 * Distance to the exact initial outline of chosen boundary faces (see boundary_depth.h).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/boundary_depth.h>

#include <deal.II/base/array_view.h>
#include <deal.II/grid/manifold_lib.h>

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ausroll::geometry
{
  using namespace dealii;

  namespace
  {
    /** Bits of the face parameter Brent's method resolves (half a double's: the squared
        distance is stationary at the foot, finer brackets only see round-off). */
    constexpr int            brent_bits = std::numeric_limits<double>::digits / 2;
    constexpr std::uintmax_t brent_iterations = 200;
  } // namespace

  template <int dim>
  BoundaryDepth<dim>::BoundaryDepth(const Triangulation<dim>        &triangulation,
                                    const std::vector<unsigned int> &ids,
                                    const std::string               &entry,
                                    const unsigned int               samples_per_edge)
      : n(std::max(2u, samples_per_edge))
  {
    std::vector<bool> found(ids.size(), false);
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const auto &face : cell->face_iterators())
      {
        if (!face->at_boundary())
          continue;
        const auto it = std::find(ids.begin(), ids.end(), face->boundary_id());
        if (it == ids.end())
          continue;
        found[it - ids.begin()] = true;
        Face f;
        f.interior = cell->center();
        for (const unsigned int v : face->vertex_indices())
          f.vertices.push_back(face->vertex(v));
        // A face that carries the cells' transfinite interpolation (the flat ends of a cylinder
        // whose cells interpolate its mantle) is the Coons patch of its edges, as deal.II
        // refines it; the transfinite manifold itself needs points inside its cells.
        // (an edge of the transfinite interpolation is straight: its ends' cells interpolate it)
        const auto own = [](const Manifold<dim> &m) -> std::unique_ptr<const Manifold<dim>>
        {
          if (dynamic_cast<const TransfiniteInterpolationManifold<dim> *>(&m))
            return std::make_unique<FlatManifold<dim>>();
          return m.clone();
        };
        if (dim == 3
            && dynamic_cast<const TransfiniteInterpolationManifold<dim> *>(&face->get_manifold()))
          for (unsigned int l = 0; l < 4; ++l)
            f.edges[l] = own(face->line(l)->get_manifold());
        else
          f.manifold = own(face->get_manifold());
        faces.push_back(std::move(f));
      }
    for (unsigned int i = 0; i < ids.size(); ++i)
      if (!found[i])
        throw InputError(entry + ": the workpiece has no boundary with id " + std::to_string(ids[i])
                         + " (the depth is measured from the boundaries listed there)");

    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
    {
      lower[d] = std::numeric_limits<double>::max();
      upper[d] = -lower[d];
    }
    const unsigned int rows = dim == 2 ? 1 : n + 1;
    for (Face &f : faces)
    {
      for (unsigned int j = 0; j < rows; ++j)
        for (unsigned int i = 0; i <= n; ++i)
        {
          f.samples.push_back(point(f, double(i) / n, double(j) / n));
          for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = std::min(lower[d], f.samples.back()[d]);
            upper[d] = std::max(upper[d], f.samples.back()[d]);
          }
        }
      // the largest distance of a sample interval's centre from its corners
      for (unsigned int j = 0; j + 1 < std::max(rows, 2u); ++j)
        for (unsigned int i = 0; i < n; ++i)
        {
          const Point<dim> centre = point(f, (i + 0.5) / n, (j + 0.5) / n);
          if (dim == 2)
            f.gap = std::max(
                {f.gap, centre.distance(f.samples[i]), centre.distance(f.samples[i + 1])});
          else
            for (const unsigned int k : {j * (n + 1) + i,
                                         j * (n + 1) + i + 1,
                                         (j + 1) * (n + 1) + i,
                                         (j + 1) * (n + 1) + i + 1})
              f.gap = std::max(f.gap, centre.distance(f.samples[k]));
        }
      f.gap *= 1.1;
    }
    extent = lower.distance(upper);
  }

  template <int dim>
  Point<dim> BoundaryDepth<dim>::point(const Face &face, const double u, const double v) const
  {
    if constexpr (dim == 2)
    {
      (void)v;
      return face.manifold->get_intermediate_point(face.vertices[0], face.vertices[1], u);
    }
    else
    {
      // deal.II's quad vertices: 0 (0, 0), 1 (1, 0), 2 (0, 1), 3 (1, 1)
      const double weights[4] = {(1. - u) * (1. - v), u * (1. - v), (1. - u) * v, u * v};
      if (face.manifold)
        return face.manifold->get_new_point(make_array_view(face.vertices),
                                            make_array_view(weights, weights + 4));
      // Coons patch of the edges: lines 0 (u = 0) and 1 (u = 1) run in v, 2 (v = 0) and 3
      // (v = 1) in u
      const auto &x = face.vertices;
      const auto  edge
          = [&](const unsigned int l, const Point<dim> &a, const Point<dim> &b, const double w)
      { return face.edges[l]->get_intermediate_point(a, b, w); };
      Point<dim> p;
      p += (1. - u) * edge(0, x[0], x[2], v) + u * edge(1, x[1], x[3], v);
      p += (1. - v) * edge(2, x[0], x[1], u) + v * edge(3, x[2], x[3], u);
      for (unsigned int k = 0; k < 4; ++k)
        p -= weights[k] * x[k];
      return p;
    }
  }

  template <int dim>
  double BoundaryDepth<dim>::refine(const Face                &face,
                                    const Point<dim>          &p,
                                    const std::vector<double> &d,
                                    const double               bound,
                                    double                    *foot_u,
                                    double                    *foot_v) const
  {
    using boost::math::tools::brent_find_minima;
    double best = *std::min_element(d.begin(), d.end());
    // the parameters of the nearest point so far: the nearest sample
    {
      const unsigned int k = std::min_element(d.begin(), d.end()) - d.begin();
      if (foot_u != nullptr)
        *foot_u = double(k % (n + 1)) / n;
      if (foot_v != nullptr)
        *foot_v = dim == 2 ? 0. : double(k / (n + 1)) / n;
    }
    const double step = 1. / n;
    const auto   bracket = [&](const double x)
    { return std::make_pair(std::max(0., x - step), std::min(1., x + step)); };
    if constexpr (dim == 2)
    {
      for (unsigned int k = 0; k <= n; ++k)
      {
        if ((k > 0 && d[k] > d[k - 1]) || (k < n && d[k] > d[k + 1]) || d[k] - face.gap > bound)
          continue;
        const auto [lo, hi] = bracket(double(k) / n);
        const auto squared = [&](const double u) { return p.distance_square(point(face, u, 0.)); };
        std::uintmax_t iterations = brent_iterations;
        const auto     minimum = brent_find_minima(squared, lo, hi, brent_bits, iterations);
        if (std::sqrt(minimum.second) < best)
        {
          best = std::sqrt(minimum.second);
          if (foot_u != nullptr)
            *foot_u = minimum.first;
        }
      }
    }
    else
    {
      const unsigned int m = n + 1;
      for (unsigned int j = 0; j <= n; ++j)
        for (unsigned int i = 0; i <= n; ++i)
        {
          const double here = d[j * m + i];
          if ((i > 0 && here > d[j * m + i - 1]) || (i < n && here > d[j * m + i + 1])
              || (j > 0 && here > d[(j - 1) * m + i]) || (j < n && here > d[(j + 1) * m + i])
              || here - face.gap > bound)
            continue;
          double u = double(i) / n, v = double(j) / n, current = here * here;
          for (unsigned int sweep = 0; sweep < 50; ++sweep)
          {
            const double   before = current;
            std::uintmax_t iterations = brent_iterations;
            const auto [u_lo, u_hi] = bracket(u);
            const auto along_u = brent_find_minima([&](const double x)
                                                   { return p.distance_square(point(face, x, v)); },
                                                   u_lo,
                                                   u_hi,
                                                   brent_bits,
                                                   iterations);
            if (along_u.second < current)
              std::tie(u, current) = along_u;
            iterations = brent_iterations;
            const auto [v_lo, v_hi] = bracket(v);
            const auto along_v = brent_find_minima([&](const double y)
                                                   { return p.distance_square(point(face, u, y)); },
                                                   v_lo,
                                                   v_hi,
                                                   brent_bits,
                                                   iterations);
            if (along_v.second < current)
              std::tie(v, current) = along_v;
            if (std::sqrt(before) - std::sqrt(current) <= 1e-15 * extent)
              break;
          }
          if (std::sqrt(current) < best)
          {
            best = std::sqrt(current);
            if (foot_u != nullptr)
              *foot_u = u;
            if (foot_v != nullptr)
              *foot_v = v;
          }
        }
    }
    return best;
  }

  template <int dim>
  double BoundaryDepth<dim>::depth(const Point<dim> &p) const
  {
    return closest(p, nullptr, nullptr, nullptr);
  }

  template <int dim>
  double BoundaryDepth<dim>::closest(const Point<dim> &p,
                                     unsigned int     *foot_face,
                                     double           *foot_u,
                                     double           *foot_v) const
  {
    // the nearest sample of every face: an upper bound of the distance, and with the gap a
    // lower bound per face
    std::vector<std::vector<double>> distances(faces.size());
    std::vector<double>              nearest(faces.size());
    double                           upper = std::numeric_limits<double>::max();
    for (unsigned int f = 0; f < faces.size(); ++f)
    {
      distances[f].resize(faces[f].samples.size());
      for (unsigned int k = 0; k < faces[f].samples.size(); ++k)
        distances[f][k] = p.distance(faces[f].samples[k]);
      nearest[f] = *std::min_element(distances[f].begin(), distances[f].end());
      upper = std::min(upper, nearest[f]);
    }
    // refine the faces in the order of their nearest sample, skipping those that cannot be nearer
    // (the first one always passes: its nearest sample is the bound)
    std::vector<unsigned int> order(faces.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      order[f] = f;
    std::sort(order.begin(),
              order.end(),
              [&](const unsigned int a, const unsigned int b) { return nearest[a] < nearest[b]; });
    double best = upper;
    bool   first = true;
    for (const unsigned int f : order)
      if (nearest[f] - faces[f].gap <= best)
      {
        double       u = 0., v = 0.;
        const double d = refine(faces[f], p, distances[f], best, &u, &v);
        if (foot_face != nullptr && (first || d < best))
        {
          *foot_face = f;
          *foot_u = u;
          *foot_v = v;
        }
        first = false;
        best = std::min(best, d);
      }
    return best;
  }

  template <int dim>
  typename BoundaryDepth<dim>::Foot BoundaryDepth<dim>::nearest(const Point<dim> &p) const
  {
    unsigned int best_face = 0;
    double       best_u = 0., best_v = 0.;
    const double best = closest(p, &best_face, &best_u, &best_v);
    const Face  &face = faces[best_face];
    Foot         foot;
    foot.point = point(face, best_u, best_v);
    foot.distance = best;
    // the face's tangent(s) by central differences (one-sided at its ends)
    const double h = 1e-5;
    const auto   tangent = [&](const unsigned int direction)
    {
      const double u0 = direction == 0 ? std::max(0., best_u - h) : best_u;
      const double u1 = direction == 0 ? std::min(1., best_u + h) : best_u;
      const double v0 = direction == 1 ? std::max(0., best_v - h) : best_v;
      const double v1 = direction == 1 ? std::min(1., best_v + h) : best_v;
      return point(face, u1, v1) - point(face, u0, v0);
    };
    Tensor<1, dim> normal;
    if constexpr (dim == 2)
    {
      const Tensor<1, dim> t = tangent(0);
      normal[0] = -t[1];
      normal[1] = t[0];
    }
    else
      normal = cross_product_3d(tangent(0), tangent(1));
    normal /= normal.norm();
    if (normal * (face.interior - foot.point) < 0.)
      normal *= -1.;
    foot.inward_normal = normal;
    return foot;
  }

  template class BoundaryDepth<2>;
  template class BoundaryDepth<3>;
} // namespace ausroll::geometry
