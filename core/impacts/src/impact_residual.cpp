#include "planarbench/impacts/impact_residual.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "planarbench/impacts/impact_error.hpp"
#include "planarbench/impacts/impact_fit.hpp"
#include "planarbench/impacts/rigid_impact.hpp"

namespace pb {

// ---- kernel ridge ----------------------------------------------------------------

struct KernelRidge::Impl {
  Eigen::MatrixXd x;  // n x d
  Eigen::MatrixXd q;  // eigenvectors of K
  Eigen::VectorXd l;  // eigenvalues of K (>= 0 up to rounding)
};

namespace {

Eigen::MatrixXd to_matrix(const std::vector<std::vector<double>>& rows) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  const auto d = n > 0 ? static_cast<Eigen::Index>(rows[0].size()) : 0;
  Eigen::MatrixXd m(n, d);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < d; ++j) {
      m(i, j) = rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    }
  }
  return m;
}

std::vector<std::vector<double>> to_rows(const Eigen::MatrixXd& m) {
  std::vector<std::vector<double>> rows(static_cast<std::size_t>(m.rows()),
                                        std::vector<double>(static_cast<std::size_t>(m.cols())));
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = m(i, j);
    }
  }
  return rows;
}

}  // namespace

KernelRidge::KernelRidge(const std::vector<std::vector<double>>& x, double length_scale)
    : length_scale_(length_scale) {
  auto impl = std::make_shared<Impl>();
  impl->x = to_matrix(x);
  const Eigen::Index n = impl->x.rows();
  Eigen::MatrixXd k(n, n);
  const double g = 1.0 / (2.0 * length_scale * length_scale);
  for (Eigen::Index i = 0; i < n; ++i) {
    k(i, i) = 1.0;
    for (Eigen::Index j = 0; j < i; ++j) {
      k(i, j) = k(j, i) = std::exp(-g * (impl->x.row(i) - impl->x.row(j)).squaredNorm());
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k);
  impl->q = eig.eigenvectors();
  impl->l = eig.eigenvalues().cwiseMax(0.0);
  impl_ = std::move(impl);
}

std::vector<std::vector<double>> KernelRidge::loo(const std::vector<std::vector<double>>& y,
                                                  double lambda) const {
  const Eigen::MatrixXd ym = to_matrix(y);
  const Eigen::VectorXd shrink = impl_->l.array() / (impl_->l.array() + lambda);
  // fitted values H y and the diagonal of H = Q diag(l / (l + lambda)) Q^T
  const Eigen::MatrixXd fitted = impl_->q * (shrink.asDiagonal() * (impl_->q.transpose() * ym));
  const Eigen::VectorXd h = impl_->q.array().square().matrix() * shrink;
  Eigen::MatrixXd out(ym.rows(), ym.cols());
  for (Eigen::Index i = 0; i < ym.rows(); ++i) {
    // y_i - (y_i - f_i) / (1 - H_ii): the prediction without impact i
    out.row(i) = ym.row(i) - (ym.row(i) - fitted.row(i)) / (1.0 - h(i));
  }
  return to_rows(out);
}

std::vector<std::vector<double>> KernelRidge::coefficients(
    const std::vector<std::vector<double>>& y, double lambda) const {
  const Eigen::MatrixXd ym = to_matrix(y);
  const Eigen::VectorXd inverse = (impl_->l.array() + lambda).inverse();
  return to_rows(impl_->q * (inverse.asDiagonal() * (impl_->q.transpose() * ym)));
}

double KernelRidge::kernel(const std::vector<double>& a, const std::vector<double>& b) const {
  double d2 = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) d2 += (a[j] - b[j]) * (a[j] - b[j]);
  return std::exp(-d2 / (2.0 * length_scale_ * length_scale_));
}

namespace {

constexpr std::size_t kFeatures = 7;

// the raw features of impact i (before standardising)
std::vector<double> raw_features(const ImpactTable& t, std::size_t i) {
  const ImpactState& b = t.before[i];
  const Vec2 r = lowest_point_offset(t.object, b.angle_rad);
  const double slip = b.velocity_mps.x() - b.angular_velocity_radps * r.y();
  return {b.velocity_mps.x(),
          b.velocity_mps.y(),
          b.angular_velocity_radps,
          slip,
          std::cos(2.0 * b.angle_rad),
          std::sin(2.0 * b.angle_rad),
          r.x()};
}

ImpactState law_prediction(const ImpactTable& t, std::size_t i, const std::vector<double>& p) {
  return rigid_compliant_impact(t.object, t.before[i],
                                CompliantImpactLaw{p[0], p[1], p[2], p[3], p[4]});
}

// what a trained residual model keeps: the law's parameters, the
// standardisation, the training features, the dual coefficients
struct Trained {
  std::vector<double> law;
  std::array<double, kFeatures> mean{};
  std::array<double, kFeatures> scale{};
  std::vector<std::vector<double>> x;      // standardised training features
  std::vector<std::vector<double>> alpha;  // n x 3
  std::shared_ptr<const KernelRidge> ridge;
  double length_scale = 0.0;
  double lambda = 0.0;

  std::vector<double> features(const ImpactTable& t, std::size_t i) const {
    std::vector<double> f = raw_features(t, i);
    for (std::size_t j = 0; j < kFeatures; ++j) f[j] = (f[j] - mean[j]) / scale[j];
    return f;
  }
};

class UntrainedPredictor final : public ImpactPredictor {
 public:
  ImpactOutcome predict(const ImpactTable&, std::size_t, const std::vector<double>&) override {
    ImpactOutcome out;
    out.failure =
        "learned_residual predicts only after training on a fit's training impacts: `impacts "
        "score` trains it on the fit's training file, which was not available";
    return out;
  }
};

class TrainedPredictor final : public ImpactPredictor {
 public:
  explicit TrainedPredictor(std::shared_ptr<const Trained> t) : t_(std::move(t)) {}
  ImpactOutcome predict(const ImpactTable& table, std::size_t i,
                        const std::vector<double>&) override {
    ImpactOutcome out;
    out.after = law_prediction(table, i, t_->law);
    const std::vector<double> f = t_->features(table, i);
    std::array<double, 3> residual{};
    for (std::size_t k = 0; k < t_->x.size(); ++k) {
      const double w = t_->ridge->kernel(f, t_->x[k]);
      for (std::size_t c = 0; c < 3; ++c) residual[c] += w * t_->alpha[k][c];
    }
    out.after.velocity_mps.x() += residual[0];
    out.after.velocity_mps.y() += residual[1];
    out.after.angular_velocity_radps += residual[2];
    return out;
  }

 private:
  std::shared_ptr<const Trained> t_;
};

std::string describe() {
  return "DATA-DRIVEN, not physics: kernel ridge regression (Gaussian kernel, on Eigen) of "
         "the measured post-impact velocities' residual from rigid_compliant's, on the "
         "pre-impact state (x', y', theta', slip, cos 2 theta, sin 2 theta, lever); law, "
         "length scale and ridge fitted on each fold's training impacts only";
}

class TrainedResidualModel final : public ImpactModel {
 public:
  explicit TrainedResidualModel(std::shared_ptr<const Trained> t) : t_(std::move(t)) {}
  std::string name() const override { return "learned_residual"; }
  std::string kind() const override { return "learned"; }
  std::string description() const override { return describe(); }
  std::vector<ImpactParameter> parameters() const override { return {}; }
  std::unique_ptr<ImpactPredictor> predictor() const override {
    return std::make_unique<TrainedPredictor>(t_);
  }

 private:
  std::shared_ptr<const Trained> t_;
};

class ResidualModel final : public ImpactModel {
 public:
  std::string name() const override { return "learned_residual"; }
  std::string kind() const override { return "learned"; }
  std::string description() const override { return describe(); }
  std::vector<ImpactParameter> parameters() const override { return {}; }
  std::unique_ptr<ImpactPredictor> predictor() const override {
    return std::make_unique<UntrainedPredictor>();
  }
  std::unique_ptr<ImpactModel> trained(const ImpactTable& table,
                                       const std::vector<std::size_t>& training,
                                       const FitOptions& options) const override;
};

std::unique_ptr<ImpactModel> ResidualModel::trained(const ImpactTable& table,
                                                    const std::vector<std::size_t>& training,
                                                    const FitOptions& options) const {
  auto t = std::make_shared<Trained>();
  // the physics law, fitted on the training impacts alone
  const std::unique_ptr<ImpactModel> law = rigid_compliant_model();
  FitOptions law_options;  // no progress: the law's evaluations are not the task's
  law_options.objective = options.objective;
  law_options.jobs = options.jobs;
  t->law = fit_impacts(*law, table, training, law_options).parameters;

  // standardised features and the law's residuals on the training impacts
  const std::size_t n = training.size();
  std::vector<std::vector<double>> raw(n);
  for (std::size_t k = 0; k < n; ++k) raw[k] = raw_features(table, training[k]);
  for (std::size_t j = 0; j < kFeatures; ++j) {
    double sum = 0.0;
    double sum2 = 0.0;
    for (const auto& f : raw) {
      sum += f[j];
      sum2 += f[j] * f[j];
    }
    const double mean = n > 0 ? sum / static_cast<double>(n) : 0.0;
    const double var = n > 0 ? sum2 / static_cast<double>(n) - mean * mean : 0.0;
    t->mean[j] = mean;
    t->scale[j] = var > 0.0 ? std::sqrt(var) : 1.0;  // a constant feature stays 0
  }
  t->x.resize(n);
  std::vector<std::vector<double>> y(n, std::vector<double>(3));
  std::vector<ImpactState> base(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = training[k];
    t->x[k] = t->features(table, i);
    base[k] = law_prediction(table, i, t->law);
    y[k] = {table.after[i].velocity_mps.x() - base[k].velocity_mps.x(),
            table.after[i].velocity_mps.y() - base[k].velocity_mps.y(),
            table.after[i].angular_velocity_radps - base[k].angular_velocity_radps};
  }
  // l and lambda: the fit's objective over the leave-one-out predictions
  double best = std::numeric_limits<double>::infinity();
  for (const double l : kResidualLengthScales) {
    auto ridge = std::make_shared<const KernelRidge>(t->x, l);
    for (const double lambda : kResidualRidges) {
      const auto loo = ridge->loo(y, lambda);
      std::vector<double> eps(n);
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = training[k];
        const std::array<double, 3> predicted = {base[k].velocity_mps.x() + loo[k][0],
                                                 base[k].velocity_mps.y() + loo[k][1],
                                                 base[k].angular_velocity_radps + loo[k][2]};
        eps[k] = impact_score(table.object, predicted, table.before[i].velocities(),
                              table.after[i].velocities())
                     .eps;
      }
      const double objective = fit_objective(eps, options.objective);
      if (objective < best) {
        best = objective;
        t->ridge = ridge;
        t->length_scale = l;
        t->lambda = lambda;
      }
    }
  }
  if (!t->ridge) t->ridge = std::make_shared<const KernelRidge>(t->x, kResidualLengthScales[0]);
  t->alpha = t->ridge->coefficients(y, t->lambda);
  return std::make_unique<TrainedResidualModel>(std::move(t));
}

}  // namespace

std::unique_ptr<ImpactModel> learned_residual_model() { return std::make_unique<ResidualModel>(); }

}  // namespace pb
