/* SPDX-License-Identifier: BSD-3-Clause */
/**
 * \file projcurve.hpp
 * \brief C++17 wrappers over the C API of libprojcurve (header only).
 *
 * Every C handle has a move-only owner that releases it (projcurve::context,
 * projcurve::options, projcurve::surface, projcurve::curve,
 * projcurve::result, projcurve::model, projcurve::face,
 * projcurve::shape_result, projcurve::iges_writer, projcurve::step_writer),
 * like a std::unique_ptr with the right deleter: get() gives the C handle,
 * release() hands it over, reset() replaces it, and a moved-from owner
 * holds nothing. Handles borrowed from another object (the surfaces,
 * curves, faces and shapes of a model) are views (projcurve::surface_view,
 * projcurve::curve_view, projcurve::face_view, projcurve::shape_view),
 * valid while their owner lives; every owner of a
 * surface, curve or face converts to its view, and the calls that only read
 * a handle take views.
 *
 * Errors: a call that fails throws projcurve::error, which carries the
 * status and the library's message for the call (read from the context
 * right after it). The calls that fail on user input have a non-throwing
 * twin, named try_..., that returns a projcurve::expected holding either
 * the value or the error. Input the wrapper can check itself (array sizes
 * that do not match, an index past the end of a model) fails the same way
 * with the C status the library would use (PROJCURVE_ERR_BAD_COUNT,
 * PROJCURVE_ERR_INDEX); the context's own message is not changed then.
 *
 * A projection stopped by a limit or by the progress callback
 * (PROJCURVE_ERR_LIMIT_REACHED, PROJCURVE_ERR_CANCELLED) is not thrown: it
 * returns its partial result, whose result::status() and result::message()
 * say why it is partial (result::complete() is false).
 *
 * Arrays are passed as projcurve::span (a pointer and a count, built from a
 * std::vector, a std::array, a C array or a braced list) and returned as
 * std::vector or std::array. Contexts are as in C: one per thread; the
 * immutable handles (surfaces, curves, results, models) may be shared
 * read-only between threads.
 *
 * Callbacks are C++ callables passed by reference (the library keeps a
 * pointer to them, not a copy: a callable given to curve::callback must
 * outlive the curve, one given to options::set_progress the options' use).
 * They return bool, true for "ok / go on"; an exception thrown by one is
 * caught at the C boundary and counts as a failure of the callback (the
 * call then fails with PROJCURVE_ERR_CALLBACK, or for progress stops with
 * PROJCURVE_ERR_CANCELLED).
 */
#ifndef PROJCURVE_HPP
#define PROJCURVE_HPP

#include "projcurve.h"

#include <array>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

/** \brief The C++ interface of libprojcurve. */
namespace projcurve {

/** \brief Status of a call (the C enum: PROJCURVE_OK, PROJCURVE_ERR_...). */
using status = projcurve_status;

/* ======================================================================== */
/* span                                                                      */
/* ======================================================================== */

/**
 * \brief A view of a contiguous array: a pointer and a count (std::span of
 * C++20, reduced to what the wrappers use).
 *
 * Built from a pointer and a count, a C array, a std::array or std::vector
 * (any container with data() and size() whose elements convert), or a
 * braced list of values (valid for the call it is passed to). It never
 * owns the elements.
 */
template <class T>
class span {
public:
    /** \brief Element type. */
    using element_type = T;

    /** \brief An empty span (NULL data). */
    constexpr span() noexcept = default;
    /** \brief count elements from data. */
    constexpr span(T *data, std::size_t count) noexcept : data_(data), size_(count) {}
    /** \brief A C array. */
    template <std::size_t N>
    constexpr span(T (&array)[N]) noexcept : data_(array), size_(N) {}
    /** \brief A container with contiguous data() and size() (vector, array, span). */
    template <class Container,
              class = std::enable_if_t<
                  !std::is_same_v<std::remove_cv_t<std::remove_reference_t<Container>>, span> &&
                  std::is_convertible_v<
                      std::remove_pointer_t<decltype(std::declval<Container &>().data())> (*)[],
                      T (*)[]>>>
    constexpr span(Container &&container) noexcept
        : data_(container.data()), size_(container.size())
    {
    }
    /** \brief A braced list (spans of const elements only; lives as long as the full
     *  expression it appears in). */
    template <class U = T, class = std::enable_if_t<std::is_const_v<U>>>
    constexpr span(std::initializer_list<std::remove_const_t<U>> list) noexcept
    {
        data_ = list.begin();
        size_ = list.size();
    }

    /** \brief The first element (NULL when empty and default-built). */
    constexpr T *data() const noexcept { return data_; }
    /** \brief Number of elements. */
    constexpr std::size_t size() const noexcept { return size_; }
    /** \brief size() == 0. */
    constexpr bool empty() const noexcept { return size_ == 0; }
    /** \brief Element i (unchecked). */
    constexpr T &operator[](std::size_t i) const noexcept { return data_[i]; }
    /** \brief Iterator to the first element. */
    constexpr T *begin() const noexcept { return data_; }
    /** \brief Iterator past the last element. */
    constexpr T *end() const noexcept { return data_ + size_; }

private:
    T *data_ = nullptr;
    std::size_t size_ = 0;
};

/* ======================================================================== */
/* Errors                                                                    */
/* ======================================================================== */

/**
 * \brief A failed call: the status and the library's message.
 *
 * what() is the message (the context's message right after the call, or
 * the status' name when the library gave none).
 */
class error : public std::runtime_error {
public:
    /** \brief An error of status s with message (the status' name when empty). */
    error(status s, const std::string &message)
        : std::runtime_error(message.empty() ? std::string(projcurve_status_string(s)) : message),
          status_(s)
    {
    }
    /** \brief The C status of the failure (never PROJCURVE_OK). */
    status code() const noexcept { return status_; }
    /** \brief The status' short English name (projcurve_status_string). */
    const char *status_name() const noexcept { return projcurve_status_string(status_); }

private:
    status status_;
};

/**
 * \brief Either a value of type T or the projcurve::error of a failed call
 * (std::expected of C++23, reduced): what the try_... calls return.
 */
template <class T>
class expected {
public:
    /** \brief A value. */
    expected(T value) : state_(std::in_place_index<0>, std::move(value)) {}
    /** \brief A failure. */
    expected(projcurve::error failure) : state_(std::in_place_index<1>, std::move(failure)) {}

    /** \brief Whether it holds a value. */
    bool has_value() const noexcept { return state_.index() == 0; }
    /** \brief Whether it holds a value. */
    explicit operator bool() const noexcept { return has_value(); }
    /** \brief The value; throws the error when there is none. */
    T &value() &
    {
        throw_if_error();
        return std::get<0>(state_);
    }
    /** \brief The value; throws the error when there is none. */
    const T &value() const &
    {
        throw_if_error();
        return std::get<0>(state_);
    }
    /** \brief The value, moved out; throws the error when there is none. */
    T &&value() &&
    {
        throw_if_error();
        return std::get<0>(std::move(state_));
    }
    /** \brief The value (unchecked). */
    T &operator*() noexcept { return *std::get_if<0>(&state_); }
    /** \brief The value (unchecked). */
    T *operator->() noexcept { return std::get_if<0>(&state_); }
    /** \brief The error; only when !has_value(). */
    const projcurve::error &error() const { return std::get<1>(state_); }
    /** \brief PROJCURVE_OK with a value, else the error's status. */
    status code() const noexcept
    {
        return has_value() ? PROJCURVE_OK : std::get_if<1>(&state_)->code();
    }

private:
    void throw_if_error() const
    {
        if (!has_value())
            throw std::get<1>(state_);
    }
    std::variant<T, projcurve::error> state_;
};

/** \brief The expected of a call without a value: success or the error. */
template <>
class expected<void> {
public:
    /** \brief Success. */
    expected() = default;
    /** \brief A failure. */
    expected(projcurve::error failure) : failure_(std::move(failure)) {}
    /** \brief Whether the call succeeded. */
    bool has_value() const noexcept { return !failure_.has_value(); }
    /** \brief Whether the call succeeded. */
    explicit operator bool() const noexcept { return has_value(); }
    /** \brief Throws the error, if any. */
    void value() const
    {
        if (failure_)
            throw *failure_;
    }
    /** \brief The error; only when !has_value(). */
    const projcurve::error &error() const { return failure_.value(); }
    /** \brief PROJCURVE_OK on success, else the error's status. */
    status code() const noexcept { return failure_ ? failure_->code() : PROJCURVE_OK; }

private:
    std::optional<projcurve::error> failure_;
};

/* ======================================================================== */
/* Version                                                                   */
/* ======================================================================== */

/** \brief Version of the loaded library, MAJOR * 10000 + MINOR * 100 + PATCH. */
inline unsigned version_number() noexcept { return projcurve_version_number(); }
/** \brief Version of the loaded library as "MAJOR.MINOR.PATCH". */
inline const char *version_string() noexcept { return projcurve_version_string(); }
/** \brief The short English name of a status. */
inline const char *status_string(status s) noexcept { return projcurve_status_string(s); }

/* ======================================================================== */
/* Context                                                                   */
/* ======================================================================== */

/**
 * \brief Owner of a projcurve_context: where a failed call leaves its
 * message. One per thread (a context must not be used by two threads at the
 * same time).
 */
class context {
public:
    /** \brief Creates a context for this header's major version; throws on failure. */
    context()
    {
        projcurve_context *raw = nullptr;
        const status s = projcurve_context_create(PROJCURVE_VERSION_MAJOR, &raw);
        if (s != PROJCURVE_OK)
            throw error(s, "projcurve_context_create failed");
        handle_ = raw;
    }
    /** \brief Takes ownership of a C context (may be NULL). */
    explicit context(projcurve_context *adopt) noexcept : handle_(adopt) {}
    context(const context &) = delete;
    context &operator=(const context &) = delete;
    /** \brief Moves the handle; other holds none afterwards. */
    context(context &&other) noexcept : handle_(other.release()) {}
    /** \brief Releases the current handle, then takes other's. */
    context &operator=(context &&other) noexcept
    {
        if (this != &other)
            reset(other.release());
        return *this;
    }
    ~context() { reset(); }

    /** \brief The C handle (still owned). */
    projcurve_context *get() const noexcept { return handle_; }
    /** \brief Whether it holds a handle. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }
    /** \brief Gives the handle up (the caller releases it). */
    projcurve_context *release() noexcept { return std::exchange(handle_, nullptr); }
    /** \brief Releases the handle and takes adopt instead. */
    void reset(projcurve_context *adopt = nullptr) noexcept
    {
        projcurve_context_destroy(std::exchange(handle_, adopt));
    }

    /** \brief Message of the last failed call ("" if none). */
    std::string message() const { return projcurve_context_message(handle_); }
    /** \brief Status of the last failed call (PROJCURVE_OK if none). */
    status last_status() const noexcept { return projcurve_context_status(handle_); }
    /** \brief Forgets the last failure. */
    void clear() noexcept { projcurve_context_clear(handle_); }

    /** \brief Sets a size limit (projcurve_context_set_limit). */
    void set_limit(projcurve_limit which, std::size_t value)
    {
        check(projcurve_context_set_limit(handle_, which, value));
    }
    /** \brief The current value of a limit. */
    std::size_t limit(projcurve_limit which) const
    {
        std::size_t value = 0;
        check(projcurve_context_get_limit(handle_, which, &value));
        return value;
    }

    /** \brief The error of a failed status s, with this context's message. */
    projcurve::error error_of(status s) const { return projcurve::error(s, message()); }
    /** \brief Throws error_of(s) unless s is PROJCURVE_OK. */
    void check(status s) const
    {
        if (s != PROJCURVE_OK)
            throw error_of(s);
    }

private:
    projcurve_context *handle_ = nullptr;
};

/// \cond PROJCURVE_DETAIL
namespace detail {

[[noreturn]] inline void fail(status s, const std::string &message) { throw error(s, message); }

/* Throws BAD_COUNT unless size is a whole number of tuples. */
inline std::size_t tuples(const char *what, std::size_t size, std::size_t dim)
{
    if (size % dim != 0)
        fail(PROJCURVE_ERR_BAD_COUNT, std::string(what) + ": " + std::to_string(size) +
                                          " values are not a whole number of " +
                                          std::to_string(dim) + "-tuples");
    return size / dim;
}

/* Throws BAD_COUNT unless an optional array is empty or has want values. */
inline const double *optional_array(const char *what, span<const double> values,
                                    std::size_t want)
{
    if (values.empty())
        return nullptr;
    if (values.size() != want)
        fail(PROJCURVE_ERR_BAD_COUNT, std::string(what) + ": " +
                                          std::to_string(values.size()) + " values, " +
                                          std::to_string(want) + " expected");
    return values.data();
}

/* The knot vector of a degree-`degree` spline with n poles has n + degree + 1
 * knots; the C calls read that many. A degree out of range is left to the
 * library, which refuses it (BAD_DEGREE) before reading any knot. */
inline const double *knots(const char *what, span<const double> knots, int degree,
                           std::size_t n)
{
    if (degree < 1 || degree > PROJCURVE_MAX_DEGREE)
        return knots.data();
    const std::size_t want = n + static_cast<std::size_t>(degree) + 1;
    if (knots.size() != want)
        fail(PROJCURVE_ERR_BAD_COUNT, std::string(what) + ": " + std::to_string(knots.size()) +
                                          " knots, degree " + std::to_string(degree) +
                                          " with " + std::to_string(n) + " poles needs " +
                                          std::to_string(want));
    return knots.data();
}

/* A borrowed handle of a model, a shape or a face: NULL means past the end. */
template <class T>
T *index_checked(T *handle, const char *what, std::size_t index, std::size_t count)
{
    if (!handle)
        fail(PROJCURVE_ERR_INDEX, std::string(what) + " " + std::to_string(index) +
                                      " is past the end (" + std::to_string(count) + ")");
    return handle;
}

/* The C user pointer of a callable (const or not; its trampoline casts it
 * back to the same F). */
template <class F>
void *user_pointer(F &callable) noexcept
{
    return const_cast<void *>(static_cast<const void *>(&callable));
}

/* Runs a throwing call and returns its expected. */
template <class F>
auto attempt(F &&f) -> expected<decltype(f())>
{
    try {
        if constexpr (std::is_void_v<decltype(f())>) {
            f();
            return {};
        } else {
            return f();
        }
    } catch (const error &e) {
        return e;
    }
}

} // namespace detail
/// \endcond

/* ======================================================================== */
/* Options                                                                   */
/* ======================================================================== */

/** \brief Type, bounds and default of an option (projcurve_option_info). */
struct option_info {
    projcurve_option_type type; ///< double or integer
    double min_value;           ///< lower bound (excluded for TOL_DISTANCE, TOL_ANGLE_DEG)
    double max_value;           ///< upper bound (inclusive)
    double default_value;       ///< the default of a new options handle
};

/** \brief Type, bounds and default of option key; throws UNKNOWN_OPTION. */
inline option_info get_option_info(context &ctx, projcurve_option key)
{
    option_info info{};
    ctx.check(projcurve_option_info(ctx.get(), key, &info.type, &info.min_value,
                                    &info.max_value, &info.default_value));
    return info;
}

/**
 * \brief Owner of a projcurve_options handle: tolerances, method and limits
 * of the projection calls. Mutable: not to be modified while another thread
 * reads it.
 */
class options {
public:
    /** \brief An empty owner (no handle). */
    options() noexcept = default;
    /** \brief New options holding every default. */
    explicit options(context &ctx)
    {
        projcurve_options *raw = nullptr;
        ctx.check(projcurve_options_create(ctx.get(), &raw));
        handle_ = raw;
    }
    /** \brief Takes ownership of a C options handle. */
    explicit options(projcurve_options *adopt) noexcept : handle_(adopt) {}
    options(const options &) = delete;
    options &operator=(const options &) = delete;
    /** \brief Moves the handle. */
    options(options &&other) noexcept : handle_(other.release()) {}
    /** \brief Releases the current handle, then takes other's. */
    options &operator=(options &&other) noexcept
    {
        if (this != &other)
            reset(other.release());
        return *this;
    }
    ~options() { reset(); }

    /** \brief The C handle (still owned). */
    projcurve_options *get() const noexcept { return handle_; }
    /** \brief Whether it holds a handle. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }
    /** \brief Gives the handle up. */
    projcurve_options *release() noexcept { return std::exchange(handle_, nullptr); }
    /** \brief Releases the handle and takes adopt instead. */
    void reset(projcurve_options *adopt = nullptr) noexcept
    {
        projcurve_options_destroy(std::exchange(handle_, adopt));
    }

    /** \brief Sets a double option; throws (WRONG_KIND, OUT_OF_RANGE, ...) leaving it unchanged. */
    options &set_double(context &ctx, projcurve_option key, double value)
    {
        ctx.check(projcurve_options_set_double(ctx.get(), handle_, key, value));
        return *this;
    }
    /** \brief Sets an integer option. */
    options &set_int(context &ctx, projcurve_option key, long long value)
    {
        ctx.check(projcurve_options_set_int(ctx.get(), handle_, key, value));
        return *this;
    }
    /** \brief A double option's value. */
    double get_double(context &ctx, projcurve_option key) const
    {
        double value = 0;
        ctx.check(projcurve_options_get_double(ctx.get(), handle_, key, &value));
        return value;
    }
    /** \brief An integer option's value. */
    long long get_int(context &ctx, projcurve_option key) const
    {
        long long value = 0;
        ctx.check(projcurve_options_get_int(ctx.get(), handle_, key, &value));
        return value;
    }

    /**
     * \brief Calls progress(fraction_done) during the projections made with
     * these options (see projcurve_options_set_progress); it returns true
     * to go on, false to stop the call (PROJCURVE_ERR_CANCELLED). progress
     * is kept by reference and must outlive its use; an exception from it
     * stops the call.
     */
    template <class F>
    options &set_progress(context &ctx, F &progress)
    {
        static_assert(std::is_same_v<std::invoke_result_t<F &, double>, bool>,
                      "a progress callable returns bool: true to go on, false to stop");
        ctx.check(projcurve_options_set_progress(ctx.get(), handle_, &progress_trampoline<F>,
                                                 detail::user_pointer(progress)));
        return *this;
    }
    /** \brief Sets a C progress callback (fn NULL: none). */
    options &set_progress(context &ctx, projcurve_progress_fn fn, void *user)
    {
        ctx.check(projcurve_options_set_progress(ctx.get(), handle_, fn, user));
        return *this;
    }
    /** \brief Removes the progress callback. */
    options &clear_progress(context &ctx) { return set_progress(ctx, nullptr, nullptr); }
    /** \brief The C callback and user pointer set (NULL, NULL when none). */
    std::pair<projcurve_progress_fn, void *> progress(context &ctx) const
    {
        projcurve_progress_fn fn = nullptr;
        void *user = nullptr;
        ctx.check(projcurve_options_get_progress(ctx.get(), handle_, &fn, &user));
        return {fn, user};
    }

private:
    template <class F>
    static int progress_trampoline(void *user, double fraction) noexcept
    {
        try {
            return (*static_cast<F *>(user))(fraction) ? 0 : 1;
        } catch (...) {
            return 1;
        }
    }
    projcurve_options *handle_ = nullptr;
};

/* ======================================================================== */
/* Curves                                                                    */
/* ======================================================================== */

/** \brief Shape of a NURBS curve (projcurve_curve_nurbs_info). */
struct curve_info {
    int degree;          ///< polynomial degree
    std::size_t n_ctrl;  ///< control points
    std::size_t n_knots; ///< knots (n_ctrl + degree + 1)
    bool rational;       ///< whether it has weights other than 1
};

/** \brief The clamped NURBS data of a curve. */
struct curve_data {
    int degree;                  ///< polynomial degree
    std::vector<double> ctrl;    ///< 3 doubles a control point
    std::vector<double> weights; ///< one a control point
    std::vector<double> knots;   ///< n_ctrl + degree + 1
};

/** \brief The closest point of a curve to a point. */
struct curve_closest {
    double t;                 ///< its parameter
    std::array<double, 3> q;  ///< the point
    double distance;          ///< |q - p|
};

/**
 * \brief A non-owning view of a curve (from a model, or of a
 * projcurve::curve). Every read-only curve call.
 */
class curve_view {
public:
    /** \brief An empty view. */
    constexpr curve_view() noexcept = default;
    /** \brief A view of a C curve handle (not owned). */
    constexpr explicit curve_view(const projcurve_curve *handle) noexcept : handle_(handle) {}

    /** \brief The C handle. */
    const projcurve_curve *get() const noexcept { return handle_; }
    /** \brief Whether it refers to a curve. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }

    /** \brief The parameter domain {t0, t1}. */
    std::array<double, 2> domain(context &ctx) const
    {
        std::array<double, 2> d{};
        ctx.check(projcurve_curve_domain(ctx.get(), handle_, &d[0], &d[1]));
        return d;
    }
    /**
     * \brief C(t) and its derivatives up to order n_deriv into out
     * (3 (n_deriv + 1) doubles: C, C', C'', C'''); throws BAD_COUNT when out
     * is too short.
     */
    void eval(context &ctx, double t, int n_deriv, span<double> out) const
    {
        if (n_deriv >= 0 && n_deriv <= 3 &&
            out.size() < 3 * static_cast<std::size_t>(n_deriv + 1))
            detail::fail(PROJCURVE_ERR_BAD_COUNT,
                         "curve eval: " + std::to_string(out.size()) + " doubles for " +
                             std::to_string(3 * (n_deriv + 1)));
        ctx.check(projcurve_curve_eval(ctx.get(), handle_, t, n_deriv, out.data()));
    }
    /** \brief The point C(t). */
    std::array<double, 3> point(context &ctx, double t) const
    {
        std::array<double, 3> p{};
        eval(ctx, t, 0, p);
        return p;
    }
    /** \brief Degree, sizes and rational flag; throws WRONG_KIND for a callback curve. */
    curve_info nurbs_info(context &ctx) const
    {
        curve_info info{};
        int rational = 0;
        ctx.check(projcurve_curve_nurbs_info(ctx.get(), handle_, &info.degree, &info.n_ctrl,
                                             &info.n_knots, &rational));
        info.rational = rational != 0;
        return info;
    }
    /** \brief The clamped NURBS data; throws WRONG_KIND for a callback curve. */
    curve_data nurbs_data(context &ctx) const
    {
        const curve_info info = nurbs_info(ctx);
        curve_data data{info.degree, std::vector<double>(3 * info.n_ctrl),
                        std::vector<double>(info.n_ctrl), std::vector<double>(info.n_knots)};
        ctx.check(projcurve_curve_nurbs_data(ctx.get(), handle_, data.ctrl.data(),
                                             data.weights.data(), data.knots.data()));
        return data;
    }
    /** \brief The closest point of the curve to p (end points included). */
    curve_closest closest_point(context &ctx, const std::array<double, 3> &p) const
    {
        curve_closest c{};
        ctx.check(projcurve_curve_closest_point(ctx.get(), handle_, p.data(), &c.t, c.q.data(),
                                                &c.distance));
        return c;
    }

protected:
    /** \brief The handle, const as every curve call reads it only. */
    const projcurve_curve *handle_ = nullptr;
};

/**
 * \brief Owner of a curve: a NURBS curve, a callback curve, or a curve the
 * library made (a branch joined, a compact form).
 */
class curve : public curve_view {
public:
    /** \brief An empty owner. */
    curve() noexcept = default;
    /** \brief Takes ownership of a C curve. */
    explicit curve(projcurve_curve *adopt) noexcept : curve_view(adopt) {}
    curve(const curve &) = delete;
    curve &operator=(const curve &) = delete;
    /** \brief Moves the handle. */
    curve(curve &&other) noexcept : curve_view(other.release()) {}
    /** \brief Releases the current handle, then takes other's. */
    curve &operator=(curve &&other) noexcept
    {
        if (this != &other)
            reset(other.release());
        return *this;
    }
    ~curve() { reset(); }

    /** \brief Gives the handle up. */
    projcurve_curve *release() noexcept
    {
        return const_cast<projcurve_curve *>(std::exchange(handle_, nullptr));
    }
    /** \brief Releases the handle and takes adopt instead. */
    void reset(projcurve_curve *adopt = nullptr) noexcept
    {
        projcurve_curve *old = release();
        handle_ = adopt;
        projcurve_curve_destroy(old);
    }

    /**
     * \brief A B-spline (weights empty) or NURBS curve: ctrl holds 3 doubles
     * a control point, weights one a point, knots n_ctrl + degree + 1 values
     * (projcurve_curve_create_nurbs; BAD_COUNT when the sizes disagree).
     */
    static curve nurbs(context &ctx, int degree, span<const double> ctrl,
                       span<const double> weights, span<const double> knots)
    {
        const std::size_t n = detail::tuples("curve control points", ctrl.size(), 3);
        const double *w = detail::optional_array("curve weights", weights, n);
        const double *k = detail::knots("curve", knots, degree, n);
        projcurve_curve *raw = nullptr;
        ctx.check(projcurve_curve_create_nurbs(ctx.get(), degree, n, ctrl.data(), w, k, &raw));
        return curve(raw);
    }
    /** \brief nurbs() without throwing. */
    static expected<curve> try_nurbs(context &ctx, int degree, span<const double> ctrl,
                                     span<const double> weights, span<const double> knots)
    {
        return detail::attempt([&] { return nurbs(ctx, degree, ctrl, weights, knots); });
    }

    /**
     * \brief A curve given by fn(t, out) over [t0, t1]: fn fills out[0..8]
     * with P(t), P'(t), P''(t) and returns true (false or an exception: the
     * call using it fails with PROJCURVE_ERR_CALLBACK). fn is kept by
     * reference and must outlive the curve; it is called from every thread
     * that uses the curve.
     */
    template <class F>
    static curve callback(context &ctx, F &fn, double t0, double t1)
    {
        static_assert(std::is_same_v<std::invoke_result_t<F &, double, double *>, bool>,
                      "a curve callable is bool(double t, double out[9])");
        projcurve_curve *raw = nullptr;
        ctx.check(projcurve_curve_create_callback(ctx.get(), &curve_trampoline<F>,
                                                  detail::user_pointer(fn), t0, t1, &raw));
        return curve(raw);
    }

private:
    template <class F>
    static int curve_trampoline(void *user, double t, double out[9]) noexcept
    {
        try {
            return (*static_cast<F *>(user))(t, out) ? 0 : 1;
        } catch (...) {
            return 1;
        }
    }
};

/* ======================================================================== */
/* Surfaces                                                                  */
/* ======================================================================== */

/** \brief Shape of a surface (projcurve_surface_info). */
struct surface_info {
    int deg_u;           ///< degree in u
    int deg_v;           ///< degree in v
    std::size_t n_u;     ///< control points in u
    std::size_t n_v;     ///< control points in v
    std::size_t spans_u; ///< non-empty knot spans in u
    std::size_t spans_v; ///< non-empty knot spans in v
    bool rational;       ///< whether it has weights other than 1
};

/** \brief The clamped NURBS data of a surface. */
struct surface_data {
    int deg_u;                   ///< degree in u
    int deg_v;                   ///< degree in v
    std::size_t n_u;             ///< control points in u
    std::size_t n_v;             ///< control points in v
    std::vector<double> ctrl;    ///< 3 n_u n_v doubles, u fastest
    std::vector<double> weights; ///< n_u n_v (all 1 when not rational)
    std::vector<double> knots_u; ///< n_u + deg_u + 1
    std::vector<double> knots_v; ///< n_v + deg_v + 1
};

/** \brief The closest point of a surface to a point. */
struct surface_closest {
    std::array<double, 2> uv; ///< its parameters
    std::array<double, 3> q;  ///< the point
    double distance;          ///< |q - p|
};

/** \brief One intersection of a line with a surface. */
struct line_hit {
    double u;       ///< parameter u of the hit
    double v;       ///< parameter v of the hit
    double lambda;  ///< the line's parameter, in units of its direction
    unsigned flags; ///< PROJCURVE_HIT_TANGENT, PROJCURVE_HIT_BOUNDARY
};

/** \brief A non-owning view of a surface. Every read-only surface call. */
class surface_view {
public:
    /** \brief An empty view. */
    constexpr surface_view() noexcept = default;
    /** \brief A view of a C surface handle (not owned). */
    constexpr explicit surface_view(const projcurve_surface *handle) noexcept : handle_(handle) {}

    /** \brief The C handle. */
    const projcurve_surface *get() const noexcept { return handle_; }
    /** \brief Whether it refers to a surface. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }

    /** \brief The domain {u0, u1, v0, v1}. */
    std::array<double, 4> domain(context &ctx) const
    {
        std::array<double, 4> d{};
        ctx.check(projcurve_surface_domain(ctx.get(), handle_, d.data()));
        return d;
    }
    /** \brief Degrees, net size, knot spans and rational flag. */
    surface_info info(context &ctx) const
    {
        surface_info i{};
        int rational = 0;
        ctx.check(projcurve_surface_info(ctx.get(), handle_, &i.deg_u, &i.deg_v, &i.n_u, &i.n_v,
                                         &i.spans_u, &i.spans_v, &rational));
        i.rational = rational != 0;
        return i;
    }
    /** \brief The clamped NURBS data. */
    surface_data nurbs_data(context &ctx) const
    {
        const surface_info i = info(ctx);
        const std::size_t n = i.n_u * i.n_v;
        surface_data d{i.deg_u,
                       i.deg_v,
                       i.n_u,
                       i.n_v,
                       std::vector<double>(3 * n),
                       std::vector<double>(n),
                       std::vector<double>(i.n_u + static_cast<std::size_t>(i.deg_u) + 1),
                       std::vector<double>(i.n_v + static_cast<std::size_t>(i.deg_v) + 1)};
        ctx.check(projcurve_surface_nurbs_data(ctx.get(), handle_, d.ctrl.data(),
                                               d.weights.data(), d.knots_u.data(),
                                               d.knots_v.data()));
        return d;
    }
    /**
     * \brief S and its partial derivatives up to total order n_deriv (0..2)
     * into out: S; Su, Sv; Suu, Suv, Svv (3 doubles each); BAD_COUNT when out
     * is too short.
     */
    void eval(context &ctx, double u, double v, int n_deriv, span<double> out) const
    {
        if (n_deriv >= 0 && n_deriv <= 2) {
            const std::size_t want =
                3 * static_cast<std::size_t>((n_deriv + 1) * (n_deriv + 2) / 2);
            if (out.size() < want)
                detail::fail(PROJCURVE_ERR_BAD_COUNT, "surface eval: " +
                                                          std::to_string(out.size()) +
                                                          " doubles for " + std::to_string(want));
        }
        ctx.check(projcurve_surface_eval(ctx.get(), handle_, u, v, n_deriv, out.data()));
    }
    /** \brief The point S(u, v). */
    std::array<double, 3> point(context &ctx, double u, double v) const
    {
        std::array<double, 3> p{};
        eval(ctx, u, v, 0, p);
        return p;
    }
    /** \brief The control net's box {xmin, ymin, zmin, xmax, ymax, zmax}. */
    std::array<double, 6> bounds(context &ctx) const
    {
        std::array<double, 6> box{};
        ctx.check(projcurve_surface_bounds(ctx.get(), handle_, box.data()));
        return box;
    }
    /** \brief The closest point of the surface to p (edges and corners included). */
    surface_closest closest_point(context &ctx, const std::array<double, 3> &p) const
    {
        surface_closest c{};
        ctx.check(projcurve_surface_closest_point(ctx.get(), handle_, p.data(), c.uv.data(),
                                                  c.q.data(), &c.distance));
        return c;
    }
    /** \brief Every interior foot point (u, v) of p, sorted by distance. */
    std::vector<std::array<double, 2>> foot_points(context &ctx,
                                                   const std::array<double, 3> &p) const
    {
        /* Two calls at most: the count, then every point (the surface does
         * not change between them). */
        std::size_t count = 0;
        ctx.check(projcurve_surface_foot_points(ctx.get(), handle_, p.data(), 0, nullptr, &count));
        std::vector<std::array<double, 2>> uv(count);
        if (count > 0) {
            ctx.check(projcurve_surface_foot_points(ctx.get(), handle_, p.data(), count,
                                                    uv.front().data(), &count));
            uv.resize(count < uv.size() ? count : uv.size());
        }
        return uv;
    }
    /**
     * \brief Every intersection of origin + lambda dir with the surface,
     * sorted by lambda (only lambda > 0 with ray_only).
     */
    std::vector<line_hit> intersect_line(context &ctx, const std::array<double, 3> &origin,
                                         const std::array<double, 3> &dir,
                                         bool ray_only = false) const
    {
        std::size_t count = 0;
        ctx.check(projcurve_surface_intersect_line(ctx.get(), handle_, origin.data(), dir.data(),
                                                   ray_only ? 1 : 0, 0, nullptr, nullptr,
                                                   &count));
        std::vector<double> hits(3 * count);
        std::vector<unsigned> flags(count);
        if (count > 0) {
            const std::size_t capacity = count;
            ctx.check(projcurve_surface_intersect_line(ctx.get(), handle_, origin.data(),
                                                       dir.data(), ray_only ? 1 : 0, capacity,
                                                       hits.data(), flags.data(), &count));
            if (count > capacity)
                count = capacity;
        }
        std::vector<line_hit> out(count);
        for (std::size_t k = 0; k < count; ++k)
            out[k] = {hits[3 * k], hits[3 * k + 1], hits[3 * k + 2], flags[k]};
        return out;
    }

protected:
    /** \brief The handle, const as every surface call reads it only. */
    const projcurve_surface *handle_ = nullptr;
};

/** \brief Owner of a B-spline or NURBS surface. */
class surface : public surface_view {
public:
    /** \brief An empty owner. */
    surface() noexcept = default;
    /** \brief Takes ownership of a C surface. */
    explicit surface(projcurve_surface *adopt) noexcept : surface_view(adopt) {}
    surface(const surface &) = delete;
    surface &operator=(const surface &) = delete;
    /** \brief Moves the handle. */
    surface(surface &&other) noexcept : surface_view(other.release()) {}
    /** \brief Releases the current handle, then takes other's. */
    surface &operator=(surface &&other) noexcept
    {
        if (this != &other)
            reset(other.release());
        return *this;
    }
    ~surface() { reset(); }

    /** \brief Gives the handle up. */
    projcurve_surface *release() noexcept
    {
        return const_cast<projcurve_surface *>(std::exchange(handle_, nullptr));
    }
    /** \brief Releases the handle and takes adopt instead. */
    void reset(projcurve_surface *adopt = nullptr) noexcept
    {
        projcurve_surface *old = release();
        handle_ = adopt;
        projcurve_surface_destroy(old);
    }

    /**
     * \brief A B-spline (weights empty) or NURBS surface from an n_u x n_v
     * net (u fastest, 3 doubles a point), n_u n_v weights and the knot
     * vectors (n_u + deg_u + 1, n_v + deg_v + 1 values); BAD_COUNT when the
     * sizes disagree (projcurve_surface_create_nurbs).
     */
    static surface nurbs(context &ctx, int deg_u, int deg_v, std::size_t n_u, std::size_t n_v,
                         span<const double> ctrl, span<const double> weights,
                         span<const double> knots_u, span<const double> knots_v)
    {
        const std::size_t n = detail::tuples("surface control points", ctrl.size(), 3);
        const bool net_matches = n_u == 0 || n_v == 0 ? n == 0 : n % n_u == 0 && n / n_u == n_v;
        if (!net_matches)
            detail::fail(PROJCURVE_ERR_BAD_COUNT,
                         "surface: " + std::to_string(n) + " control points for a " +
                             std::to_string(n_u) + " x " + std::to_string(n_v) + " net");
        const double *w = detail::optional_array("surface weights", weights, n);
        const double *ku = detail::knots("surface u", knots_u, deg_u, n_u);
        const double *kv = detail::knots("surface v", knots_v, deg_v, n_v);
        projcurve_surface *raw = nullptr;
        ctx.check(projcurve_surface_create_nurbs(ctx.get(), deg_u, deg_v, n_u, n_v, ctrl.data(), w,
                                                 ku, kv, &raw));
        return surface(raw);
    }
    /** \brief nurbs() without throwing. */
    static expected<surface> try_nurbs(context &ctx, int deg_u, int deg_v, std::size_t n_u,
                                       std::size_t n_v, span<const double> ctrl,
                                       span<const double> weights, span<const double> knots_u,
                                       span<const double> knots_v)
    {
        return detail::attempt(
            [&] { return nurbs(ctx, deg_u, deg_v, n_u, n_v, ctrl, weights, knots_u, knots_v); });
    }
};

/* ======================================================================== */
/* Results                                                                   */
/* ======================================================================== */

/** \brief Summary of a branch (projcurve_result_branch_info). */
struct branch_info {
    std::array<double, 2> t_range; ///< curve parameter range
    projcurve_branch_start start;  ///< why it starts
    projcurve_branch_end end;      ///< why it ends
    std::size_t n_points;          ///< traced points
    std::size_t n_pieces;          ///< composed pieces
};

/** \brief One composed Bezier piece of a branch. */
struct bezier_piece {
    int degree;                    ///< its degree
    std::vector<double> ctrl;      ///< degree + 1 points, 3 doubles each
    std::vector<double> weights;   ///< degree + 1 (all 1 when not rational)
    std::array<double, 2> range;   ///< curve parameter range
    std::array<double, 4> uv_range; ///< (u, v) at its start, then at its end
};

/** \brief The pcurve of a composed piece: a Bezier curve in (u, v) over s in [0, 1]. */
struct piece_pcurve {
    int degree;                  ///< 1 or 3
    std::vector<double> uv_ctrl; ///< degree + 1 (u, v) pairs
};

/** \brief What the fit of a branch's compact forms measured. */
struct compact_info {
    bool pcurve_fitted;  ///< a fitted pcurve (false: the pieces' pcurves joined)
    double pcurve_error; ///< largest distance of S o q from the projection (-1: no fit)
    double curve_error;  ///< the same for the compact 3D curve
};

/** \brief A jump of a branch's pcurve where it crosses a seam or passes a pole. */
struct seam_jump {
    double t;  ///< the curve parameter of the jump
    double du; ///< u just after minus u just before
    double dv; ///< v just after minus v just before
};

/**
 * \brief Owner of a projection result: its branches, their points, pieces
 * and compact curves, and the status of the call that made it (a partial
 * result has status() PROJCURVE_ERR_LIMIT_REACHED or
 * PROJCURVE_ERR_CANCELLED).
 */
class result {
public:
    /** \brief An empty owner. */
    result() noexcept = default;
    /** \brief Takes ownership of a C result, made by a call that returned s
     *  with message. */
    explicit result(projcurve_result *adopt, status s = PROJCURVE_OK,
                    std::string message = std::string()) noexcept
        : handle_(adopt), status_(s), message_(std::move(message))
    {
    }
    result(const result &) = delete;
    result &operator=(const result &) = delete;
    /** \brief Moves the handle and the call's status. */
    result(result &&other) noexcept
        : handle_(other.release()), status_(other.status_), message_(std::move(other.message_))
    {
    }
    /** \brief Releases the current handle, then takes other's. */
    result &operator=(result &&other) noexcept
    {
        if (this != &other) {
            status_ = other.status_;
            message_ = std::move(other.message_);
            reset(other.release());
        }
        return *this;
    }
    ~result() { reset(); }

    /** \brief The C handle (still owned). */
    const projcurve_result *get() const noexcept { return handle_; }
    /** \brief Whether it holds a handle. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }
    /** \brief Gives the handle up. */
    projcurve_result *release() noexcept { return std::exchange(handle_, nullptr); }
    /** \brief Releases the handle and takes adopt instead. */
    void reset(projcurve_result *adopt = nullptr) noexcept
    {
        projcurve_result_destroy(std::exchange(handle_, adopt));
    }

    /** \brief The status of the call: OK, LIMIT_REACHED or CANCELLED. */
    status code() const noexcept { return status_; }
    /** \brief The context's message when the call stopped early ("" when complete). */
    const std::string &message() const noexcept { return message_; }
    /** \brief Whether the call ran to its end (status PROJCURVE_OK). */
    bool complete() const noexcept { return status_ == PROJCURVE_OK; }

    /** \brief Number of branches. */
    std::size_t branch_count() const noexcept { return projcurve_result_branch_count(handle_); }
    /** \brief Places the library could not follow or verify (0: the whole projection). */
    std::size_t failure_count() const noexcept { return projcurve_result_failure_count(handle_); }
    /** \brief 3 for (t, u, v) points, 4 for (t, x, y, z) points of implicit results. */
    int point_dim() const noexcept { return projcurve_result_point_dim(handle_); }
    /** \brief A statistic (PROJCURVE_STAT_...). */
    double stat(context &ctx, projcurve_stat key) const
    {
        double value = 0;
        ctx.check(projcurve_result_stat(ctx.get(), handle_, key, &value));
        return value;
    }
    /** \brief Summary of branch b; throws INDEX past the end. */
    branch_info branch(context &ctx, std::size_t b) const
    {
        branch_info info{};
        ctx.check(projcurve_result_branch_info(ctx.get(), handle_, b, info.t_range.data(),
                                               &info.start, &info.end, &info.n_points,
                                               &info.n_pieces));
        return info;
    }
    /** \brief The traced points of branch b, point_dim() doubles each. */
    std::vector<double> branch_points(context &ctx, std::size_t b) const
    {
        std::size_t count = 0;
        ctx.check(projcurve_result_branch_points(ctx.get(), handle_, b, 0, nullptr, &count));
        const std::size_t dim = static_cast<std::size_t>(point_dim());
        std::vector<double> points(dim * count);
        if (count > 0) {
            const std::size_t capacity = count;
            ctx.check(projcurve_result_branch_points(ctx.get(), handle_, b, capacity,
                                                     points.data(), &count));
            points.resize(dim * (count < capacity ? count : capacity));
        }
        return points;
    }
    /** \brief Composed piece p of branch b. */
    bezier_piece piece(context &ctx, std::size_t b, std::size_t p) const
    {
        bezier_piece out{0, std::vector<double>(3 * PROJCURVE_MAX_PIECE_POINTS),
                         std::vector<double>(PROJCURVE_MAX_PIECE_POINTS), {}, {}};
        ctx.check(projcurve_result_piece(ctx.get(), handle_, b, p, &out.degree, out.ctrl.data(),
                                         out.weights.data(), out.range.data(),
                                         out.uv_range.data()));
        const std::size_t n = static_cast<std::size_t>(out.degree) + 1;
        out.ctrl.resize(3 * n);
        out.weights.resize(n);
        return out;
    }
    /** \brief The (u, v) Bezier curve of piece p of branch b. */
    piece_pcurve pcurve(context &ctx, std::size_t b, std::size_t p) const
    {
        piece_pcurve out{0, std::vector<double>(2 * PROJCURVE_MAX_PCURVE_POINTS)};
        ctx.check(projcurve_result_piece_pcurve(ctx.get(), handle_, b, p, &out.degree,
                                                out.uv_ctrl.data()));
        out.uv_ctrl.resize(2 * (static_cast<std::size_t>(out.degree) + 1));
        return out;
    }
    /** \brief Branch b's pieces joined into one NURBS curve (exactly on S). */
    curve branch_curve(context &ctx, std::size_t b) const
    {
        projcurve_curve *raw = nullptr;
        ctx.check(projcurve_result_branch_curve(ctx.get(), handle_, b, &raw));
        return curve(raw);
    }
    /** \brief Branch b's compact pcurve, control points (u, v, 0). */
    curve compact_pcurve(context &ctx, std::size_t b) const
    {
        projcurve_curve *raw = nullptr;
        ctx.check(projcurve_result_branch_compact_pcurve(ctx.get(), handle_, b, &raw));
        return curve(raw);
    }
    /** \brief Branch b's compact 3D curve. */
    curve compact_curve(context &ctx, std::size_t b) const
    {
        projcurve_curve *raw = nullptr;
        ctx.check(projcurve_result_branch_compact_curve(ctx.get(), handle_, b, &raw));
        return curve(raw);
    }
    /** \brief Branch b's compact pcurve composed exactly with s, the
     *  surface the result was projected onto
     *  (projcurve_result_branch_compact_exact): one NURBS curve on s to
     *  rounding, of degree 3 (p + q) for the cubic pcurve (rational when
     *  s or the pcurve is: a pcurve in a rational curve's space, degree
     *  2 (p + q) for a circle onto a plane). Its Bezier parts (q cut at
     *  its knots, seam jumps and the knot lines of s) are joined with
     *  knots of multiplicity the degree
     *  where they meet only C0 (seams, poles, creases of q or s) and of
     *  lower multiplicity where S o q is smoother (C2 at a simple knot of
     *  q inside a patch, C^(p - m) across a knot line of multiplicity m):
     *  the copies removed move the curve by at most 256 ulps of its
     *  size. */
    curve compact_exact(context &ctx, surface_view s, std::size_t b) const
    {
        projcurve_curve *raw = nullptr;
        ctx.check(projcurve_result_branch_compact_exact(ctx.get(), handle_, s.get(), b, &raw));
        return curve(raw);
    }
    /** \brief What the fit of branch b's compact forms measured. */
    compact_info compact(context &ctx, std::size_t b) const
    {
        compact_info info{};
        int fitted = 0;
        ctx.check(projcurve_result_branch_compact_info(ctx.get(), handle_, b, &fitted,
                                                       &info.pcurve_error, &info.curve_error));
        info.pcurve_fitted = fitted != 0;
        return info;
    }
    /** \brief The jumps of branch b's pcurve in increasing t
     *  (projcurve_result_branch_seam); empty when it crosses no seam. */
    std::vector<seam_jump> seams(context &ctx, std::size_t b) const
    {
        std::size_t n = 0;
        ctx.check(projcurve_result_branch_seam_count(ctx.get(), handle_, b, &n));
        std::vector<seam_jump> out(n);
        for (std::size_t k = 0; k < n; ++k)
            ctx.check(projcurve_result_branch_seam(ctx.get(), handle_, b, k, &out[k].t,
                                                   &out[k].du, &out[k].dv));
        return out;
    }

private:
    projcurve_result *handle_ = nullptr;
    status status_ = PROJCURVE_OK;
    std::string message_;
};

/// \cond PROJCURVE_DETAIL
namespace detail {

/* The result of a projection call: thrown unless it is complete or partial
 * with a result (LIMIT_REACHED and CANCELLED set *out). */
inline result projection(context &ctx, status s, projcurve_result *raw)
{
    if (s == PROJCURVE_OK)
        return result(raw);
    if ((s == PROJCURVE_ERR_LIMIT_REACHED || s == PROJCURVE_ERR_CANCELLED) && raw)
        return result(raw, s, ctx.message());
    projcurve_result_destroy(raw);
    throw ctx.error_of(s);
}

/* The results of a many-curve call: one per curve, each with its curve's
 * status (an empty owner where the call kept none); thrown when the call
 * failed as a whole (no statuses[i] is its status: nothing was projected). */
inline std::vector<result> curve_results(context &ctx, status st,
                                         std::vector<projcurve_result *> &raw,
                                         const std::vector<projcurve_status> &statuses)
{
    std::size_t first = statuses.size();
    for (std::size_t i = 0; i < statuses.size() && first == statuses.size(); ++i)
        if (st != PROJCURVE_OK && statuses[i] == st)
            first = i;
    if (st != PROJCURVE_OK && first == statuses.size()) {
        for (projcurve_result *r : raw)
            projcurve_result_destroy(r);
        throw ctx.error_of(st);
    }
    std::vector<result> out;
    out.reserve(raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i) {
        std::string why;
        if (i == first) {
            why = ctx.message();
            const std::string prefix = "curve " + std::to_string(i) + ": ";
            if (why.compare(0, prefix.size(), prefix) == 0)
                why.erase(0, prefix.size());
        } else if (statuses[i] != PROJCURVE_OK) {
            why = projcurve_status_string(statuses[i]);
        }
        out.emplace_back(std::exchange(raw[i], nullptr), statuses[i], std::move(why));
    }
    return out;
}

template <class Curves>
std::vector<const projcurve_curve *> curve_handles(const Curves &curves)
{
    std::vector<const projcurve_curve *> out;
    for (const auto &c : curves)
        out.push_back(static_cast<const curve_view &>(c).get());
    return out;
}

template <class F>
int implicit_trampoline(void *user, const double x[3], double *value, double grad[3],
                        double hess[9]) noexcept
{
    try {
        return (*static_cast<F *>(user))(x, *value, grad, hess) ? 0 : 1;
    } catch (...) {
        return 1;
    }
}

} // namespace detail
/// \endcond

/* ======================================================================== */
/* Projection                                                                */
/* ======================================================================== */

/**
 * \brief Directional projection of c onto s along dir
 * (projcurve_project_directional); opts NULL: the defaults. A call stopped
 * by a limit or cancelled returns its partial result (result::complete()
 * false); any other failure throws.
 */
inline result project_directional(context &ctx, surface_view s, curve_view c,
                                  const std::array<double, 3> &dir,
                                  const options *opts = nullptr)
{
    projcurve_result *raw = nullptr;
    const status st = projcurve_project_directional(ctx.get(), s.get(), c.get(), dir.data(),
                                                    opts ? opts->get() : nullptr, &raw);
    return detail::projection(ctx, st, raw);
}
/** \brief project_directional() with options. */
inline result project_directional(context &ctx, surface_view s, curve_view c,
                                  const std::array<double, 3> &dir, const options &opts)
{
    return project_directional(ctx, s, c, dir, &opts);
}
/** \brief project_directional() without throwing. */
inline expected<result> try_project_directional(context &ctx, surface_view s, curve_view c,
                                                const std::array<double, 3> &dir,
                                                const options *opts = nullptr)
{
    return detail::attempt([&] { return project_directional(ctx, s, c, dir, opts); });
}

/**
 * \brief Conical (central) projection of c onto s from the eye point eye
 * (projcurve_project_conical): P(t) maps to the points of s on the ray
 * from eye through P(t), beyond P(t). As project_directional() for
 * partial results and errors; a curve through the eye throws an error
 * with status PROJCURVE_ERR_SINGULAR.
 */
inline result project_conical(context &ctx, surface_view s, curve_view c,
                              const std::array<double, 3> &eye, const options *opts = nullptr)
{
    projcurve_result *raw = nullptr;
    const status st = projcurve_project_conical(ctx.get(), s.get(), c.get(), eye.data(),
                                                opts ? opts->get() : nullptr, &raw);
    return detail::projection(ctx, st, raw);
}
/** \brief project_conical() with options. */
inline result project_conical(context &ctx, surface_view s, curve_view c,
                              const std::array<double, 3> &eye, const options &opts)
{
    return project_conical(ctx, s, c, eye, &opts);
}
/** \brief project_conical() without throwing. */
inline expected<result> try_project_conical(context &ctx, surface_view s, curve_view c,
                                            const std::array<double, 3> &eye,
                                            const options *opts = nullptr)
{
    return detail::attempt([&] { return project_conical(ctx, s, c, eye, opts); });
}

/** \brief Orthogonal projection of c onto s (projcurve_project_orthogonal); as
 *  project_directional() for partial results and errors. */
inline result project_orthogonal(context &ctx, surface_view s, curve_view c,
                                 const options *opts = nullptr)
{
    projcurve_result *raw = nullptr;
    const status st = projcurve_project_orthogonal(ctx.get(), s.get(), c.get(),
                                                   opts ? opts->get() : nullptr, &raw);
    return detail::projection(ctx, st, raw);
}
/** \brief project_orthogonal() with options. */
inline result project_orthogonal(context &ctx, surface_view s, curve_view c,
                                 const options &opts)
{
    return project_orthogonal(ctx, s, c, &opts);
}
/** \brief project_orthogonal() without throwing. */
inline expected<result> try_project_orthogonal(context &ctx, surface_view s, curve_view c,
                                               const options *opts = nullptr)
{
    return detail::attempt([&] { return project_orthogonal(ctx, s, c, opts); });
}

/**
 * \brief Many curves onto s along dir in one call
 * (projcurve_project_curves_directional): curves is a container of
 * curve or curve_view. Returns one result per curve, the same as
 * project_directional() gives it, whatever PROJCURVE_OPT_THREADS is; a
 * curve that failed has its status in code() and message() (and an empty
 * owner when its call kept no result). Throws when the call fails as a
 * whole (zero or non-finite dir, bad options, out of memory).
 */
template <class Curves>
std::vector<result> project_curves_directional(context &ctx, surface_view s, const Curves &curves,
                                               const std::array<double, 3> &dir,
                                               const options *opts = nullptr)
{
    const std::vector<const projcurve_curve *> handles = detail::curve_handles(curves);
    std::vector<projcurve_result *> raw(handles.size(), nullptr);
    std::vector<projcurve_status> statuses(handles.size(), PROJCURVE_OK);
    const status st = projcurve_project_curves_directional(
        ctx.get(), s.get(), handles.data(), handles.size(), dir.data(),
        opts ? opts->get() : nullptr, raw.data(), statuses.data());
    return detail::curve_results(ctx, st, raw, statuses);
}

/** \brief Many curves orthogonally onto s (projcurve_project_curves_orthogonal);
 *  as project_curves_directional(). */
template <class Curves>
std::vector<result> project_curves_orthogonal(context &ctx, surface_view s, const Curves &curves,
                                              const options *opts = nullptr)
{
    const std::vector<const projcurve_curve *> handles = detail::curve_handles(curves);
    std::vector<projcurve_result *> raw(handles.size(), nullptr);
    std::vector<projcurve_status> statuses(handles.size(), PROJCURVE_OK);
    const status st = projcurve_project_curves_orthogonal(ctx.get(), s.get(), handles.data(),
                                                          handles.size(),
                                                          opts ? opts->get() : nullptr, raw.data(),
                                                          statuses.data());
    return detail::curve_results(ctx, st, raw, statuses);
}

/**
 * \brief Orthogonal projection onto the implicit surface f(x) = 0
 * (projcurve_project_orthogonal_implicit): f(x, value, grad, hess) sets
 * the value, gradient and row-major Hessian at x and returns true. f is
 * called only during this call.
 */
template <class F>
result project_orthogonal_implicit(context &ctx, F &f, double model_size, curve_view c,
                                   const options *opts = nullptr)
{
    static_assert(std::is_same_v<std::invoke_result_t<F &, const double *, double &, double *,
                                                      double *>,
                                 bool>,
                  "an implicit surface callable is "
                  "bool(const double x[3], double &value, double grad[3], double hess[9])");
    projcurve_result *raw = nullptr;
    const status st = projcurve_project_orthogonal_implicit(
        ctx.get(), &detail::implicit_trampoline<F>, detail::user_pointer(f), model_size, c.get(),
        opts ? opts->get() : nullptr, &raw);
    return detail::projection(ctx, st, raw);
}

/* ======================================================================== */
/* Faces and shapes                                                          */
/* ======================================================================== */

/** \brief A trimming piece's curve as stored by a face (arrays borrowed from the face). */
struct face_piece {
    int degree;                  ///< its degree
    span<const double> ctrl;     ///< (u, v) control points, 2 doubles each
    span<const double> weights;  ///< one a point; empty for a polynomial piece
    span<const double> knots;    ///< n_ctrl + degree + 1
    int sense;                   ///< +1: the loop runs along the curve's parameter
};

/** \brief The 3D edge of a trimming piece. */
struct piece_edge {
    long edge;      ///< the model's id of the edge, -1 when none
    int edge_sense; ///< +1 when the curve runs along the edge
    unsigned flags; ///< PROJCURVE_PIECE_SEAM, _DEGENERATE, _NATURAL
};

/** \brief A face's boxes: (u, v) of the outer loop and 3D. */
struct face_bounds {
    std::array<double, 4> uv;  ///< {u0, u1, v0, v1}
    std::array<double, 6> box; ///< {x0, y0, z0, x1, y1, z1}
};

/** \brief A face's tolerances. */
struct face_tolerance {
    double uv;    ///< width of ON in (u, v)
    double model; ///< the model precision it was made for (0 for a caller's face)
};

/** \brief Orientation, closure and kind of a face's surface. */
struct face_info {
    int same_sense;                 ///< +1: normal Su x Sv; -1: opposite
    std::array<bool, 2> periodic;   ///< closes across u, across v
    std::string_view kind;          ///< "bspline", "plane", ... (static storage)
};

/** \brief A non-owning view of a face (of a model or a shape, or of a projcurve::face). */
class face_view {
public:
    /** \brief An empty view. */
    constexpr face_view() noexcept = default;
    /** \brief A view of a C face (not owned). */
    constexpr explicit face_view(const projcurve_face *handle) noexcept : handle_(handle) {}

    /** \brief The C handle. */
    const projcurve_face *get() const noexcept { return handle_; }
    /** \brief Whether it refers to a face. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }

    /** \brief The face's surface (borrowed). */
    surface_view surface() const noexcept { return surface_view(projcurve_face_surface(handle_)); }
    /** \brief Loops, the outer one first. */
    std::size_t loop_count() const noexcept { return projcurve_face_loop_count(handle_); }
    /** \brief Pieces of a loop. */
    std::size_t piece_count(context &ctx, std::size_t loop) const
    {
        std::size_t count = 0;
        ctx.check(projcurve_face_loop_piece_count(ctx.get(), handle_, loop, &count));
        return count;
    }
    /** \brief A piece's curve (arrays valid while the face lives). */
    face_piece piece(context &ctx, std::size_t loop, std::size_t p) const
    {
        int degree = 0, sense = 0;
        std::size_t n = 0;
        const double *ctrl = nullptr, *weights = nullptr, *knots = nullptr;
        ctx.check(projcurve_face_piece_curve(ctx.get(), handle_, loop, p, &degree, &n, &ctrl,
                                             &weights, &knots, &sense));
        const std::size_t n_knots = n + static_cast<std::size_t>(degree) + 1;
        return {degree, span<const double>(ctrl, 2 * n),
                weights ? span<const double>(weights, n) : span<const double>(),
                span<const double>(knots, n_knots), sense};
    }
    /** \brief A piece's 3D edge. */
    piece_edge edge(context &ctx, std::size_t loop, std::size_t p) const
    {
        piece_edge e{};
        ctx.check(projcurve_face_piece_edge(ctx.get(), handle_, loop, p, &e.edge, &e.edge_sense,
                                            &e.flags));
        return e;
    }
    /** \brief Where (u, v) is: PROJCURVE_IN, PROJCURVE_OUT or PROJCURVE_ON. */
    projcurve_where classify(context &ctx, double u, double v) const
    {
        projcurve_where where = PROJCURVE_OUT;
        ctx.check(projcurve_face_classify(ctx.get(), handle_, u, v, &where));
        return where;
    }
    /** \brief The (u, v) box of the outer loop and a 3D box holding the face. */
    face_bounds bounds(context &ctx) const
    {
        face_bounds b{};
        ctx.check(projcurve_face_bounds(ctx.get(), handle_, b.uv.data(), b.box.data()));
        return b;
    }
    /** \brief The face's tolerances. */
    face_tolerance tolerance(context &ctx) const
    {
        face_tolerance t{};
        ctx.check(projcurve_face_tolerance(ctx.get(), handle_, &t.uv, &t.model));
        return t;
    }
    /** \brief Orientation, closure and surface kind. */
    face_info info(context &ctx) const
    {
        int same_sense = 0;
        int periodic[2] = {0, 0};
        const char *kind = nullptr;
        ctx.check(projcurve_face_info(ctx.get(), handle_, &same_sense, periodic, &kind));
        return {same_sense, {periodic[0] != 0, periodic[1] != 0},
                kind ? std::string_view(kind) : std::string_view()};
    }

protected:
    /** \brief The handle, const as every face call reads it only. */
    const projcurve_face *handle_ = nullptr;
};

/** \brief A trimming piece given to face::create: a 2D NURBS curve in (u, v). */
struct trim_curve {
    int degree;                 ///< its degree
    span<const double> ctrl;    ///< (u, v) control points, 2 doubles each
    span<const double> weights; ///< empty for a polynomial piece
    span<const double> knots;   ///< n_ctrl + degree + 1
};

/** \brief Owner of a face made by face::create; it borrows its surface, which must
 *  outlive it. */
class face : public face_view {
public:
    /** \brief An empty owner. */
    face() noexcept = default;
    /** \brief Takes ownership of a C face made by projcurve_face_create. */
    explicit face(projcurve_face *adopt) noexcept : face_view(adopt) {}
    face(const face &) = delete;
    face &operator=(const face &) = delete;
    /** \brief Moves the handle. */
    face(face &&other) noexcept : face_view(other.release()) {}
    /** \brief Releases the current handle, then takes other's. */
    face &operator=(face &&other) noexcept
    {
        if (this != &other)
            reset(other.release());
        return *this;
    }
    ~face() { reset(); }

    /** \brief Gives the handle up. */
    projcurve_face *release() noexcept
    {
        return const_cast<projcurve_face *>(std::exchange(handle_, nullptr));
    }
    /** \brief Releases the handle and takes adopt instead. */
    void reset(projcurve_face *adopt = nullptr) noexcept
    {
        projcurve_face *old = release();
        handle_ = adopt;
        projcurve_face_destroy(old);
    }

    /**
     * \brief A face on s from loops, the outer one first (none: the whole
     * domain): loop k is the next loop_pieces[k] entries of pieces
     * (projcurve_face_create). tol_uv 0: 1e-9 of the domain's size.
     * BAD_COUNT when the sizes disagree.
     */
    static face create(context &ctx, surface_view s, span<const std::size_t> loop_pieces,
                       span<const trim_curve> pieces, double tol_uv = 0)
    {
        std::size_t total = 0;
        for (const std::size_t n : loop_pieces)
            total += n;
        if (total != pieces.size())
            detail::fail(PROJCURVE_ERR_BAD_COUNT,
                         "face: the loops count " + std::to_string(total) + " pieces, " +
                             std::to_string(pieces.size()) + " given");
        std::vector<int> degrees(pieces.size());
        std::vector<std::size_t> n_ctrl(pieces.size());
        std::vector<const double *> ctrl(pieces.size()), weights(pieces.size()),
            knots(pieces.size());
        for (std::size_t j = 0; j < pieces.size(); ++j) {
            const trim_curve &c = pieces[j];
            degrees[j] = c.degree;
            n_ctrl[j] = detail::tuples("face piece control points", c.ctrl.size(), 2);
            ctrl[j] = c.ctrl.data();
            weights[j] = detail::optional_array("face piece weights", c.weights, n_ctrl[j]);
            knots[j] = detail::knots("face piece", c.knots, c.degree, n_ctrl[j]);
        }
        projcurve_face *raw = nullptr;
        ctx.check(projcurve_face_create(ctx.get(), s.get(), loop_pieces.size(),
                                        loop_pieces.data(), degrees.data(), n_ctrl.data(),
                                        ctrl.data(), weights.data(), knots.data(), tol_uv, &raw));
        return face(raw);
    }
};

/** \brief One use of a shape's edge by a face piece. */
struct edge_use {
    std::size_t face;  ///< the shape's face index
    std::size_t loop;  ///< loop of that face
    std::size_t piece; ///< piece of that loop
    int sense;         ///< +1 when the loop runs along the edge
};

/** \brief A shape's edge. */
struct shape_edge {
    long id;            ///< the model's id
    std::size_t n_uses; ///< face pieces using it
};

/** \brief Kind of a shape and the tolerance its faces were sewn with. */
struct shape_info {
    projcurve_shape_kind kind; ///< solid, closed or open shell, face set
    double sew_tol;            ///< 0 when the file gave the edges
};

/** \brief A non-owning view of a shape of a model: faces and the edges they share. */
class shape_view {
public:
    /** \brief An empty view. */
    constexpr shape_view() noexcept = default;
    /** \brief A view of a C shape (not owned). */
    constexpr explicit shape_view(const projcurve_shape *handle) noexcept : handle_(handle) {}

    /** \brief The C handle. */
    const projcurve_shape *get() const noexcept { return handle_; }
    /** \brief Whether it refers to a shape. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }

    /** \brief Kind and sewing tolerance. */
    shape_info info(context &ctx) const
    {
        shape_info i{};
        ctx.check(projcurve_shape_info(ctx.get(), handle_, &i.kind, &i.sew_tol));
        return i;
    }
    /** \brief Number of faces. */
    std::size_t face_count() const noexcept { return projcurve_shape_face_count(handle_); }
    /** \brief Face i; throws INDEX past the end. */
    face_view face(std::size_t i) const
    {
        return face_view(detail::index_checked(projcurve_shape_face(handle_, i), "shape face", i,
                                               face_count()));
    }
    /** \brief The model's index of face i. */
    std::size_t face_model_index(context &ctx, std::size_t i) const
    {
        std::size_t index = 0;
        ctx.check(projcurve_shape_face_model_index(ctx.get(), handle_, i, &index));
        return index;
    }
    /** \brief Number of edges. */
    std::size_t edge_count() const noexcept { return projcurve_shape_edge_count(handle_); }
    /** \brief Edge e's id and use count. */
    shape_edge edge(context &ctx, std::size_t e) const
    {
        shape_edge out{};
        ctx.check(projcurve_shape_edge(ctx.get(), handle_, e, &out.id, &out.n_uses));
        return out;
    }
    /** \brief Use k of edge e. */
    edge_use use(context &ctx, std::size_t e, std::size_t k) const
    {
        edge_use out{};
        ctx.check(projcurve_shape_edge_use(ctx.get(), handle_, e, k, &out.face, &out.loop,
                                           &out.piece, &out.sense));
        return out;
    }

private:
    const projcurve_shape *handle_ = nullptr;
};

/* ======================================================================== */
/* Models                                                                    */
/* ======================================================================== */

/**
 * \brief Owner of a model read from an IGES, STEP or G+Smo XML file: its
 * surfaces, curves, faces and shapes are views valid while it lives.
 */
class model {
public:
    /** \brief An empty owner. */
    model() noexcept = default;
    /** \brief Takes ownership of a C model. */
    explicit model(projcurve_model *adopt) noexcept : handle_(adopt) {}
    model(const model &) = delete;
    model &operator=(const model &) = delete;
    /** \brief Moves the handle. */
    model(model &&other) noexcept : handle_(other.release()) {}
    /** \brief Releases the current handle, then takes other's. */
    model &operator=(model &&other) noexcept
    {
        if (this != &other)
            reset(other.release());
        return *this;
    }
    ~model() { reset(); }

    /** \brief The C handle (still owned). */
    const projcurve_model *get() const noexcept { return handle_; }
    /** \brief Whether it holds a handle. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }
    /** \brief Gives the handle up. */
    projcurve_model *release() noexcept { return std::exchange(handle_, nullptr); }
    /** \brief Releases the handle and takes adopt instead. */
    void reset(projcurve_model *adopt = nullptr) noexcept
    {
        projcurve_model_destroy(std::exchange(handle_, adopt));
    }

    /** \brief Reads a file (IGES, STEP or G+Smo XML, recognised by content). */
    static model read_file(context &ctx, const std::string &path)
    {
        projcurve_model *raw = nullptr;
        ctx.check(projcurve_model_read_file(ctx.get(), path.c_str(), &raw));
        return model(raw);
    }
    /** \brief read_file() without throwing. */
    static expected<model> try_read_file(context &ctx, const std::string &path)
    {
        return detail::attempt([&] { return read_file(ctx, path); });
    }
    /** \brief Reads a file's contents from memory. */
    static model read_memory(context &ctx, std::string_view data)
    {
        projcurve_model *raw = nullptr;
        ctx.check(projcurve_model_read_memory(ctx.get(), data.data(), data.size(), &raw));
        return model(raw);
    }
    /** \brief read_memory() without throwing. */
    static expected<model> try_read_memory(context &ctx, std::string_view data)
    {
        return detail::attempt([&] { return read_memory(ctx, data); });
    }

    /** \brief Number of surfaces. */
    std::size_t surface_count() const noexcept { return projcurve_model_surface_count(handle_); }
    /** \brief Number of curves. */
    std::size_t curve_count() const noexcept { return projcurve_model_curve_count(handle_); }
    /** \brief Number of entities not read. */
    std::size_t skipped_count() const noexcept { return projcurve_model_skipped_count(handle_); }
    /** \brief Surface i; throws INDEX past the end. */
    surface_view surface(std::size_t i) const
    {
        return surface_view(detail::index_checked(projcurve_model_surface(handle_, i),
                                                  "model surface", i, surface_count()));
    }
    /** \brief Curve i; throws INDEX past the end. */
    curve_view curve(std::size_t i) const
    {
        return curve_view(detail::index_checked(projcurve_model_curve(handle_, i), "model curve",
                                                i, curve_count()));
    }
    /** \brief Description of skipped entity i. */
    std::string_view skipped(std::size_t i) const
    {
        return detail::index_checked(projcurve_model_skipped(handle_, i), "model skipped entity",
                                     i, skipped_count());
    }
    /** \brief The file's kind of surface i ("bspline", "plane", ...). */
    std::string_view surface_kind(std::size_t i) const
    {
        return detail::index_checked(projcurve_model_surface_kind(handle_, i), "model surface",
                                     i, surface_count());
    }
    /** \brief The file's length unit in metres, if it states one. */
    std::optional<double> length_unit() const noexcept
    {
        double metres = 0;
        if (projcurve_model_length_unit(handle_, &metres))
            return metres;
        return std::nullopt;
    }
    /** \brief The file's distance precision in model units, if it states one. */
    std::optional<double> precision() const noexcept
    {
        double precision = 0;
        if (projcurve_model_precision(handle_, &precision))
            return precision;
        return std::nullopt;
    }
    /** \brief Number of faces built. */
    std::size_t face_count() const noexcept { return projcurve_model_face_count(handle_); }
    /** \brief Face i; throws INDEX past the end. */
    face_view face(std::size_t i) const
    {
        return face_view(detail::index_checked(projcurve_model_face(handle_, i), "model face", i,
                                               face_count()));
    }
    /** \brief Number of shapes. */
    std::size_t shape_count() const noexcept { return projcurve_model_shape_count(handle_); }
    /** \brief Shape i; throws INDEX past the end. */
    shape_view shape(std::size_t i) const
    {
        return shape_view(detail::index_checked(projcurve_model_shape(handle_, i), "model shape",
                                                i, shape_count()));
    }
    /** \brief Number of faces that could not be built. */
    std::size_t unbuilt_face_count() const noexcept
    {
        return projcurve_model_unbuilt_face_count(handle_);
    }
    /** \brief Why face i could not be built. */
    std::string_view unbuilt_face(std::size_t i) const
    {
        return detail::index_checked(projcurve_model_unbuilt_face(handle_, i),
                                     "model unbuilt face", i, unbuilt_face_count());
    }
    /** \brief The file's surface kind of unbuilt face i. */
    std::string_view unbuilt_face_kind(std::size_t i) const
    {
        return detail::index_checked(projcurve_model_unbuilt_face_kind(handle_, i),
                                     "model unbuilt face", i, unbuilt_face_count());
    }

private:
    projcurve_model *handle_ = nullptr;
};

/* ======================================================================== */
/* Projection onto faces and shapes                                          */
/* ======================================================================== */

/** \brief A connected curve of a shape_result. */
struct connected_curve {
    std::size_t n_pieces;          ///< its face pieces
    std::array<double, 2> t_range; ///< t of its first piece's start, of its last piece's end
    bool closed;                   ///< its last piece chains into its first
};

/** \brief A face piece of a connected curve: branch `branch` of the face's
 *  result (borrowed from the shape_result; read it with the
 *  projcurve_result_* functions). */
struct shape_piece {
    std::size_t face;                   ///< index of its face in the shape
    const projcurve_result *face_result; ///< the face's clipped result
    std::size_t branch;                 ///< its branch there
    std::array<double, 2> t_range;      ///< its curve-parameter range
    projcurve_branch_start start;       ///< why it starts
    projcurve_branch_end end;           ///< why it ends
};

/** \brief A projected face of a shape_result. */
struct face_outcome {
    std::size_t face;               ///< index of the face in the shape
    const projcurve_result *result; ///< its clipped result (borrowed; NULL when it failed)
    status code;                    ///< the status of its projection
    std::string message;            ///< its message ("" on OK)
};

/** \brief Owner of the result of project_face() / project_shape(): per face
 *  a clipped result, and the face pieces chained into connected curves. */
class shape_result {
public:
    /** \brief An empty owner. */
    shape_result() noexcept = default;
    /** \brief Takes ownership of a C shape result made by a call that returned s. */
    explicit shape_result(projcurve_shape_result *adopt, status s = PROJCURVE_OK,
                          std::string message = std::string()) noexcept
        : handle_(adopt), status_(s), message_(std::move(message))
    {
    }
    shape_result(const shape_result &) = delete;
    shape_result &operator=(const shape_result &) = delete;
    /** \brief Moves the handle and the call's status. */
    shape_result(shape_result &&other) noexcept
        : handle_(other.release()), status_(other.status_), message_(std::move(other.message_))
    {
    }
    /** \brief Releases the current handle, then takes other's. */
    shape_result &operator=(shape_result &&other) noexcept
    {
        if (this != &other) {
            status_ = other.status_;
            message_ = std::move(other.message_);
            reset(other.release());
        }
        return *this;
    }
    ~shape_result() { reset(); }

    /** \brief The C handle (still owned). */
    const projcurve_shape_result *get() const noexcept { return handle_; }
    /** \brief Whether it holds a handle. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }
    /** \brief Gives the handle up. */
    projcurve_shape_result *release() noexcept { return std::exchange(handle_, nullptr); }
    /** \brief Releases the handle and takes adopt instead. */
    void reset(projcurve_shape_result *adopt = nullptr) noexcept
    {
        projcurve_shape_result_destroy(std::exchange(handle_, adopt));
    }
    /** \brief The status of the call: OK, LIMIT_REACHED or CANCELLED. */
    status code() const noexcept { return status_; }
    /** \brief The context's message when the call stopped early. */
    const std::string &message() const noexcept { return message_; }
    /** \brief Whether the call ran to its end. */
    bool complete() const noexcept { return status_ == PROJCURVE_OK; }

    /** \brief The number of connected curves. */
    std::size_t curve_count() const noexcept { return projcurve_shape_result_curve_count(handle_); }
    /** \brief Connected curve k. */
    connected_curve curve(context &ctx, std::size_t k) const
    {
        connected_curve c{};
        int closed = 0;
        ctx.check(projcurve_shape_result_curve_info(ctx.get(), handle_, k, &c.n_pieces,
                                                    c.t_range.data(), &closed));
        c.closed = closed != 0;
        return c;
    }
    /** \brief Face piece j of connected curve k. */
    shape_piece piece(context &ctx, std::size_t k, std::size_t j) const
    {
        shape_piece p{};
        ctx.check(projcurve_shape_result_piece(ctx.get(), handle_, k, j, &p.face, &p.face_result,
                                               &p.branch, p.t_range.data(), &p.start, &p.end));
        return p;
    }
    /** \brief The number of faces projected. */
    std::size_t face_count() const noexcept { return projcurve_shape_result_face_count(handle_); }
    /** \brief Projected face i. */
    face_outcome face(context &ctx, std::size_t i) const
    {
        face_outcome f{};
        const char *why = nullptr;
        ctx.check(projcurve_shape_result_face(ctx.get(), handle_, i, &f.face, &f.result, &f.code,
                                              &why));
        f.message = why ? why : "";
        return f;
    }
    /** \brief Ends on an edge that found no continuation where one was due. */
    std::size_t open_end_count() const noexcept
    {
        return projcurve_shape_result_open_end_count(handle_);
    }
    /** \brief The chaining tolerance, model units. */
    double chain_tolerance() const noexcept
    {
        return projcurve_shape_result_chain_tolerance(handle_);
    }

private:
    projcurve_shape_result *handle_ = nullptr;
    status status_ = PROJCURVE_OK;
    std::string message_;
};

/// \cond PROJCURVE_DETAIL
namespace detail {
inline shape_result shape_projection(context &ctx, status s, projcurve_shape_result *raw)
{
    if (s == PROJCURVE_OK)
        return shape_result(raw);
    if ((s == PROJCURVE_ERR_LIMIT_REACHED || s == PROJCURVE_ERR_CANCELLED) && raw)
        return shape_result(raw, s, ctx.message());
    projcurve_shape_result_destroy(raw);
    throw ctx.error_of(s);
}
} // namespace detail
/// \endcond

/**
 * \brief Projection of c onto face f (projcurve_project_face): kind
 * PROJCURVE_PROJECT_DIRECTIONAL with vec the direction, or
 * PROJCURVE_PROJECT_ORTHOGONAL (vec unused). A partial result is returned
 * (shape_result::complete() false); any other failure throws.
 */
inline shape_result project_face(context &ctx, face_view f, curve_view c,
                                 projcurve_projection_kind kind,
                                 const std::array<double, 3> &vec = {0, 0, 0},
                                 const options *opts = nullptr)
{
    projcurve_shape_result *raw = nullptr;
    const status st = projcurve_project_face(ctx.get(), f.get(), c.get(), kind, vec.data(),
                                             opts ? opts->get() : nullptr, &raw);
    return detail::shape_projection(ctx, st, raw);
}

/** \brief Projection of c onto every face of shape sh it reaches, chained into
 *  connected curves (projcurve_project_shape); as project_face(). */
inline shape_result project_shape(context &ctx, shape_view sh, curve_view c,
                                  projcurve_projection_kind kind,
                                  const std::array<double, 3> &vec = {0, 0, 0},
                                  const options *opts = nullptr)
{
    projcurve_shape_result *raw = nullptr;
    const status st = projcurve_project_shape(ctx.get(), sh.get(), c.get(), kind, vec.data(),
                                              opts ? opts->get() : nullptr, &raw);
    return detail::shape_projection(ctx, st, raw);
}

/* ======================================================================== */
/* IGES output                                                               */
/* ======================================================================== */

/** \brief Owner of an IGES writer: collects surfaces, curves and results, then
 *  writes one IGES 5.3 file. One thread at a time. */
class iges_writer {
public:
    /** \brief An empty owner. */
    iges_writer() noexcept = default;
    /** \brief A new, empty writer. */
    explicit iges_writer(context &ctx)
    {
        projcurve_iges_writer *raw = nullptr;
        ctx.check(projcurve_iges_writer_create(ctx.get(), &raw));
        handle_ = raw;
    }
    /** \brief Takes ownership of a C writer. */
    explicit iges_writer(projcurve_iges_writer *adopt) noexcept : handle_(adopt) {}
    iges_writer(const iges_writer &) = delete;
    iges_writer &operator=(const iges_writer &) = delete;
    /** \brief Moves the handle. */
    iges_writer(iges_writer &&other) noexcept : handle_(other.release()) {}
    /** \brief Releases the current handle, then takes other's. */
    iges_writer &operator=(iges_writer &&other) noexcept
    {
        if (this != &other)
            reset(other.release());
        return *this;
    }
    ~iges_writer() { reset(); }

    /** \brief The C handle (still owned). */
    projcurve_iges_writer *get() const noexcept { return handle_; }
    /** \brief Whether it holds a handle. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }
    /** \brief Gives the handle up. */
    projcurve_iges_writer *release() noexcept { return std::exchange(handle_, nullptr); }
    /** \brief Releases the handle and takes adopt instead. */
    void reset(projcurve_iges_writer *adopt = nullptr) noexcept
    {
        projcurve_iges_writer_destroy(std::exchange(handle_, adopt));
    }

    /** \brief Adds a surface (copied). */
    iges_writer &add_surface(context &ctx, surface_view s)
    {
        ctx.check(projcurve_iges_writer_add_surface(ctx.get(), handle_, s.get()));
        return *this;
    }
    /** \brief Adds a NURBS curve. */
    iges_writer &add_curve(context &ctx, curve_view c)
    {
        ctx.check(projcurve_iges_writer_add_curve(ctx.get(), handle_, c.get()));
        return *this;
    }
    /** \brief Adds every branch of r onto s in its compact forms. */
    iges_writer &add_result(context &ctx, surface_view s, const result &r)
    {
        ctx.check(projcurve_iges_writer_add_result(ctx.get(), handle_, s.get(), r.get()));
        return *this;
    }
    /** \brief Adds every branch of r onto s as its composed pieces joined. */
    iges_writer &add_result_pieces(context &ctx, surface_view s, const result &r)
    {
        ctx.check(projcurve_iges_writer_add_result_pieces(ctx.get(), handle_, s.get(), r.get()));
        return *this;
    }
    /** \brief The file's length unit in metres per unit (default 0.001, mm). */
    iges_writer &set_length_unit(context &ctx, double metres_per_unit)
    {
        ctx.check(projcurve_iges_writer_set_length_unit(ctx.get(), handle_, metres_per_unit));
        return *this;
    }
    /** \brief Writes the file. */
    void write(context &ctx, const std::string &path) const
    {
        ctx.check(projcurve_iges_writer_write(ctx.get(), handle_, path.c_str()));
    }
    /** \brief Adds every connected curve of r as one composite curve (102)
     *  of its face pieces' 3D curves. */
    iges_writer &add_shape_result(context &ctx, const shape_result &r)
    {
        ctx.check(projcurve_iges_writer_add_shape_result(ctx.get(), handle_, r.get()));
        return *this;
    }
    /** \brief write() without throwing. */
    expected<void> try_write(context &ctx, const std::string &path) const
    {
        return detail::attempt([&] { write(ctx, path); });
    }

private:
    projcurve_iges_writer *handle_ = nullptr;
};

/* ======================================================================== */
/* STEP output                                                               */
/* ======================================================================== */

/** \brief Owner of a STEP writer: collects surfaces, curves and results, then
 *  writes one STEP AP214 file. One thread at a time. */
class step_writer {
public:
    /** \brief An empty owner. */
    step_writer() noexcept = default;
    /** \brief A new, empty writer (millimetres, uncertainty 1e-7). */
    explicit step_writer(context &ctx)
    {
        projcurve_step_writer *raw = nullptr;
        ctx.check(projcurve_step_writer_create(ctx.get(), &raw));
        handle_ = raw;
    }
    /** \brief Takes ownership of a C writer. */
    explicit step_writer(projcurve_step_writer *adopt) noexcept : handle_(adopt) {}
    step_writer(const step_writer &) = delete;
    step_writer &operator=(const step_writer &) = delete;
    /** \brief Moves the handle. */
    step_writer(step_writer &&other) noexcept : handle_(other.release()) {}
    /** \brief Releases the current handle, then takes other's. */
    step_writer &operator=(step_writer &&other) noexcept
    {
        if (this != &other)
            reset(other.release());
        return *this;
    }
    ~step_writer() { reset(); }

    /** \brief The C handle (still owned). */
    projcurve_step_writer *get() const noexcept { return handle_; }
    /** \brief Whether it holds a handle. */
    explicit operator bool() const noexcept { return handle_ != nullptr; }
    /** \brief Gives the handle up. */
    projcurve_step_writer *release() noexcept { return std::exchange(handle_, nullptr); }
    /** \brief Releases the handle and takes adopt instead. */
    void reset(projcurve_step_writer *adopt = nullptr) noexcept
    {
        projcurve_step_writer_destroy(std::exchange(handle_, adopt));
    }

    /** \brief Adds a surface (written once however often it is added). */
    step_writer &add_surface(context &ctx, surface_view s)
    {
        ctx.check(projcurve_step_writer_add_surface(ctx.get(), handle_, s.get()));
        return *this;
    }
    /** \brief Adds a NURBS curve. */
    step_writer &add_curve(context &ctx, curve_view c)
    {
        ctx.check(projcurve_step_writer_add_curve(ctx.get(), handle_, c.get()));
        return *this;
    }
    /** \brief Adds every branch of r onto s as a SURFACE_CURVE (compact curve
     *  and pcurve); the writer is left as it was when it throws. */
    step_writer &add_result(context &ctx, surface_view s, const result &r)
    {
        ctx.check(projcurve_step_writer_add_result(ctx.get(), handle_, s.get(), r.get()));
        return *this;
    }
    /** \brief The file's length unit in metres per unit (default 0.001, mm). */
    step_writer &set_length_unit(context &ctx, double metres_per_unit)
    {
        ctx.check(projcurve_step_writer_set_length_unit(ctx.get(), handle_, metres_per_unit));
        return *this;
    }
    /** \brief The file's distance uncertainty in model units, written as given. */
    step_writer &set_uncertainty(context &ctx, double distance)
    {
        ctx.check(projcurve_step_writer_set_uncertainty(ctx.get(), handle_, distance));
        return *this;
    }
    /** \brief Writes the file; the writer stays usable. */
    void write(context &ctx, const std::string &path) const
    {
        ctx.check(projcurve_step_writer_write(ctx.get(), handle_, path.c_str()));
    }
    /** \brief Adds every connected curve of r as one COMPOSITE_CURVE of its
     *  face pieces' 3D curves. */
    step_writer &add_shape_result(context &ctx, const shape_result &r)
    {
        ctx.check(projcurve_step_writer_add_shape_result(ctx.get(), handle_, r.get()));
        return *this;
    }
    /** \brief write() without throwing. */
    expected<void> try_write(context &ctx, const std::string &path) const
    {
        return detail::attempt([&] { write(ctx, path); });
    }

private:
    projcurve_step_writer *handle_ = nullptr;
};

} // namespace projcurve

#endif /* PROJCURVE_HPP */
