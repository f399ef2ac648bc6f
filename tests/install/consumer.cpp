/* SPDX-License-Identifier: BSD-3-Clause */
// The C++ view of the installed libprojcurve: the C header must compile as
// C++ (extern "C", no C-only constructs) and link without name mangling, and
// the installed C++ wrappers (projcurve.hpp, C++17) must build warning-free
// and work: a projection through them, its handles released by their
// owners, and a failure thrown as projcurve::error with the library's
// message.
#include <projcurve.h>
#include <projcurve.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace {

struct context_deleter {
    void operator()(projcurve_context *ctx) const { projcurve_context_destroy(ctx); }
};
struct options_deleter {
    void operator()(projcurve_options *opts) const { projcurve_options_destroy(opts); }
};

// The C API with hand-written deleters.
bool c_api_from_cpp()
{
    projcurve_context *raw_ctx = nullptr;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &raw_ctx) != PROJCURVE_OK)
        return false;
    std::unique_ptr<projcurve_context, context_deleter> ctx(raw_ctx);

    projcurve_options *raw_opts = nullptr;
    if (projcurve_options_create(ctx.get(), &raw_opts) != PROJCURVE_OK)
        return false;
    std::unique_ptr<projcurve_options, options_deleter> opts(raw_opts);

    long long iterations = 0;
    if (projcurve_options_get_int(ctx.get(), opts.get(), PROJCURVE_OPT_NEWTON_MAX_ITER,
                                  &iterations) != PROJCURVE_OK)
        return false;
    const projcurve_status s =
        projcurve_options_set_int(ctx.get(), opts.get(), static_cast<projcurve_option>(999), 1);
    const std::string message = projcurve_context_message(ctx.get());
    std::printf("C++ consumer: libprojcurve %s, NEWTON_MAX_ITER = %lld, bad key -> %s: %s\n",
                projcurve_version_string(), iterations, projcurve_status_string(s),
                message.c_str());
    return iterations == 20 && s == PROJCURVE_ERR_UNKNOWN_OPTION &&
           message.find("999") != std::string::npos;
}

// The same kind of use through the wrappers: the README's line onto the
// saddle S(u, v) = (u, v, uv) along -z, whose projection at t is
// (x(t), y(t), x(t) y(t)).
bool wrappers()
{
    namespace pc = projcurve;
    pc::context ctx;
    const double net[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1}, knots[] = {0, 0, 1, 1};
    const pc::surface s = pc::surface::nurbs(ctx, 1, 1, 2, 2, net, {}, knots, knots);
    const pc::curve c = pc::curve::nurbs(ctx, 1, {0.1, 0.2, 2, 0.9, 0.7, 2}, {}, knots);
    pc::options opts(ctx);
    opts.set_double(ctx, PROJCURVE_OPT_TOL_DISTANCE, 1e-6);
    const pc::result r = pc::project_directional(ctx, s, c, {0, 0, -1}, opts);
    const pc::curve image = r.compact_curve(ctx, 0);
    const std::array<double, 3> mid = image.point(ctx, 0.5);
    const double x = 0.5, y = 0.45;
    // Within eps_D (1e-6) of the exact projection.
    const bool on = std::fabs(mid[0] - x) <= 1e-6 && std::fabs(mid[1] - y) <= 1e-6 &&
                    std::fabs(mid[2] - x * y) <= 1e-6;
    std::string message;
    try {
        pc::project_directional(ctx, s, c, {0, 0, 0});
    } catch (const pc::error &e) {
        message = e.what();
        std::printf("C++ wrappers: %zu branch, C(0.5) = (%g, %g, %g); zero direction -> %s: %s\n",
                    r.branch_count(), mid[0], mid[1], mid[2], e.status_name(), e.what());
        return r.branch_count() == 1 && on && e.code() == PROJCURVE_ERR_ZERO_DIRECTION &&
               !message.empty();
    }
    return false;
}

} // namespace

int main()
{
    const bool c_ok = c_api_from_cpp();
    const bool cpp_ok = wrappers();
    return c_ok && cpp_ok ? 0 : 1;
}
