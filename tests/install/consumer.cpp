/* SPDX-License-Identifier: BSD-3-Clause */
// The C++ view of the installed libprojcurve: the header must compile as
// C++ (extern "C", no C-only constructs) and link without name mangling.
#include <projcurve.h>

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

} // namespace

int main()
{
    projcurve_context *raw_ctx = nullptr;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &raw_ctx) != PROJCURVE_OK)
        return 1;
    std::unique_ptr<projcurve_context, context_deleter> ctx(raw_ctx);

    projcurve_options *raw_opts = nullptr;
    if (projcurve_options_create(ctx.get(), &raw_opts) != PROJCURVE_OK)
        return 1;
    std::unique_ptr<projcurve_options, options_deleter> opts(raw_opts);

    long long iterations = 0;
    if (projcurve_options_get_int(ctx.get(), opts.get(), PROJCURVE_OPT_NEWTON_MAX_ITER,
                                  &iterations) != PROJCURVE_OK)
        return 1;
    const projcurve_status s =
        projcurve_options_set_int(ctx.get(), opts.get(), static_cast<projcurve_option>(999), 1);
    const std::string message = projcurve_context_message(ctx.get());
    std::printf("C++ consumer: libprojcurve %s, NEWTON_MAX_ITER = %lld, bad key -> %s: %s\n",
                projcurve_version_string(), iterations, projcurve_status_string(s),
                message.c_str());
    return (iterations == 20 && s == PROJCURVE_ERR_UNKNOWN_OPTION &&
            message.find("999") != std::string::npos)
               ? 0
               : 1;
}
