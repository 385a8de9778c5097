// fit_spectral_weights.cpp — how core/src/spectral_data.cpp's kXyzWeights
// were fitted (sky_spectral.hpp, "The matrices"): the XYZ weights of a set
// of solved wavelengths, least squares on single-scattering spectra of
// Bruneton 2017's Earth (ozone x0.6, 1, 1.6; Mie x1, 5), each spectrum's
// error relative to its luminance, the white held exact by a penalty, a
// small ridge towards linear-interpolation weights; then the worst du'v'
// and luminance error of the fit and of linear interpolation against 41
// wavelengths at the zenith and the horizon for suns 90 .. -6 deg.
// Not part of the build (a tool, seconds to run):
//   g++ -O2 -std=c++20 tests/tools/fit_spectral_weights.cpp -o /tmp/fit
//   /tmp/fit 430,470,520,570,610,660      (nm; several sets may follow)
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>
// 10 nm data 360..830 (48)
static const double kSolar[48] = {1.11776, 1.14259, 1.01249, 1.14716, 1.72765, 1.73054, 1.6887,  1.61253,
                                  1.91198, 2.03474, 2.02042, 2.02212, 1.93377, 1.95809, 1.91686, 1.8298,
                                  1.8685,  1.8931,  1.85149, 1.8504,  1.8341,  1.8345,  1.8147,  1.78158,
                                  1.7533,  1.6965,  1.68194, 1.64654, 1.6048,  1.52143, 1.55622, 1.5113,
                                  1.474,   1.4482,  1.41018, 1.36775, 1.34188, 1.31429, 1.28303, 1.26758,
                                  1.2367,  1.2082,  1.18737, 1.14683, 1.12362, 1.1058,  1.07124, 1.04992};
static const double kOzone[48] = {1.18e-27,  2.182e-28, 2.818e-28, 6.636e-28, 1.527e-27, 2.763e-27, 5.52e-27,
                                  8.451e-27, 1.582e-26, 2.316e-26, 3.669e-26, 4.924e-26, 7.752e-26, 9.016e-26,
                                  1.48e-25,  1.602e-25, 2.139e-25, 2.755e-25, 3.091e-25, 3.5e-25,   4.266e-25,
                                  4.672e-25, 4.398e-25, 4.701e-25, 5.019e-25, 4.305e-25, 3.74e-25,  3.215e-25,
                                  2.662e-25, 2.238e-25, 1.852e-25, 1.473e-25, 1.209e-25, 9.423e-26, 7.455e-26,
                                  6.566e-26, 5.105e-26, 4.15e-26,  4.228e-26, 3.237e-26, 2.451e-26, 2.801e-26,
                                  2.534e-26, 1.624e-26, 1.465e-26, 2.078e-26, 1.383e-26, 7.105e-27};
// CIE 1931 2 deg, 380..780 step 10 (41)
static const double kCmf[41][3] = {{0.001368, 0.000039, 0.006450001},
                                   {0.004243, 0.000120, 0.02005001},
                                   {0.01431, 0.000396, 0.06785001},
                                   {0.04351, 0.00121, 0.2074},
                                   {0.13438, 0.004, 0.6456},
                                   {0.2839, 0.0116, 1.3856},
                                   {0.34828, 0.023, 1.74706},
                                   {0.3362, 0.038, 1.77211},
                                   {0.2908, 0.06, 1.6692},
                                   {0.19536, 0.09098, 1.28764},
                                   {0.09564, 0.13902, 0.8129501},
                                   {0.03201, 0.20802, 0.46518},
                                   {0.0049, 0.323, 0.272},
                                   {0.0093, 0.503, 0.1582},
                                   {0.06327, 0.71, 0.07824999},
                                   {0.1655, 0.862, 0.04216},
                                   {0.2904, 0.954, 0.0203},
                                   {0.4334499, 0.9949501, 0.008749999},
                                   {0.5945, 0.995, 0.0039},
                                   {0.7621, 0.952, 0.0021},
                                   {0.9163, 0.87, 0.001650001},
                                   {1.0263, 0.757, 0.0011},
                                   {1.0622, 0.631, 0.0008},
                                   {1.0026, 0.503, 0.00034},
                                   {0.8544499, 0.381, 0.00019},
                                   {0.6424, 0.265, 0.00004999999},
                                   {0.4479, 0.175, 0.00002},
                                   {0.2835, 0.107, 0.0},
                                   {0.1649, 0.061, 0.0},
                                   {0.0874, 0.032, 0.0},
                                   {0.04677, 0.017, 0.0},
                                   {0.0227, 0.00821, 0.0},
                                   {0.01135916, 0.004102, 0.0},
                                   {0.005790346, 0.002091, 0.0},
                                   {0.002899327, 0.001047, 0.0},
                                   {0.001439971, 0.00052, 0.0},
                                   {0.0006900786, 0.0002492, 0.0},
                                   {0.0003323011, 0.00012, 0.0},
                                   {0.0001661505, 0.00006, 0.0},
                                   {0.00008307527, 0.00003, 0.0},
                                   {0.00004150994, 0.00001499, 0.0}};
const double Rg = 6360000, Rt = 6420000, PI = 3.14159265358979;
double Mie_s = 3.996e-6, Mie_e = 3.996e-6 / 0.9;
const double HR = 8000, HM = 1200, NO3 = 300 * 2.687e20 / 15000, g = 0.8;
struct V {
    double x, y, z;
};
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V add(V a, V b, double t) { return {a.x + b.x * t, a.y + b.y * t, a.z + b.z * t}; }
struct Dens {
    double r, m, o;
};
Dens dens(double h) {
    return {std::exp(-h / HR), std::exp(-h / HM), std::max(0.0, 1 - std::fabs(h - 25000) / 15000)};
}
double tTop(V x, V d) {
    double b = dot(x, d), c = dot(x, x) - Rt * Rt;
    double D = b * b - c;
    return D < 0 ? 0 : -b + std::sqrt(D);
}
Dens depth(V x, V d, double t0, double t1, int n, int mode) {  // mode 0: dense at t0, 1: dense at t1
    Dens s{0, 0, 0};
    for (int k = 0; k < n; ++k) {
        double u0 = double(k) / n, u1 = double(k + 1) / n, um = (k + 0.5) / n;
        double a, b, m;
        if (mode == 0) {
            a = t0 + (t1 - t0) * u0 * u0;
            b = t0 + (t1 - t0) * u1 * u1;
            m = t0 + (t1 - t0) * um * um;
        } else {
            a = t1 - (t1 - t0) * (1 - u0) * (1 - u0);
            b = t1 - (t1 - t0) * (1 - u1) * (1 - u1);
            m = t1 - (t1 - t0) * (1 - um) * (1 - um);
        }
        V p = add(x, d, m);
        double h = std::sqrt(dot(p, p)) - Rg;
        Dens q = dens(h);
        double dt = b - a;
        s.r += q.r * dt;
        s.m += q.m * dt;
        s.o += q.o * dt;
    }
    return s;
}
struct Samp {
    double wr, wm;
    Dens tau;
};
struct Ray {
    std::vector<Samp> s;
    double mu;
};
int NV = 1000, NS = 200;
Ray trace(double sunEl, double el, double az) {
    V s{std::cos(sunEl), std::sin(sunEl), 0};
    V v{std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az)};
    V x0{0, Rg, 0};
    double L = tTop(x0, v);
    Ray R;
    R.mu = dot(v, s);
    Dens tv{0, 0, 0};
    for (int k = 0; k < NV; ++k) {
        double u0 = double(k) / NV, u1 = double(k + 1) / NV, um = (k + 0.5) / NV;
        double a = L * u0 * u0, b = L * u1 * u1, m = L * um * um, dt = b - a;
        V p = add(x0, v, m);
        double r = std::sqrt(dot(p, p));
        Dens q = dens(r - Rg);
        Dens tvm{tv.r + q.r * dt * 0.5, tv.m + q.m * dt * 0.5, tv.o + q.o * dt * 0.5};
        tv.r += q.r * dt;
        tv.m += q.m * dt;
        tv.o += q.o * dt;
        double tstar = -dot(p, s);
        double c2 = dot(p, p) - tstar * tstar;
        if (tstar > 0 && c2 < Rg * Rg) continue;
        double Ls = tTop(p, s);
        Dens ts;
        if (tstar > 0) {
            Dens a1 = depth(p, s, 0, tstar, NS, 1), a2 = depth(p, s, tstar, Ls, NS, 0);
            ts = {a1.r + a2.r, a1.m + a2.m, a1.o + a2.o};
        } else
            ts = depth(p, s, 0, Ls, NS, 0);
        R.s.push_back({q.r * dt, q.m * dt, {tvm.r + ts.r, tvm.m + ts.m, tvm.o + ts.o}});
    }
    return R;
}
double ozoneX(double lam) {
    double u = (lam - 360) / 10;
    int i = std::clamp(int(std::floor(u)), 0, 46);
    u -= i;
    return kOzone[i] * (1 - u) + kOzone[i + 1] * u;
}
double rayl(double lam) {
    double l = lam * 1e-3;
    return 1.24062e-6 / (l * l * l * l);
}
double PR(double mu) { return 3 / (16 * PI) * (1 + mu * mu); }
double PM(double mu) {
    return 3 / (8 * PI) * (1 - g * g) * (1 + mu * mu) / ((2 + g * g) * std::pow(1 + g * g - 2 * g * mu, 1.5));
}
double ozScale = 1;
double evalF(const Ray& R, double lam) {
    double sr = rayl(lam), so = NO3 * ozoneX(lam) * ozScale;
    double IR = 0, IM = 0;
    for (auto& q : R.s) {
        double T = std::exp(-(sr * q.tau.r + Mie_e * q.tau.m + so * q.tau.o));
        IR += q.wr * T;
        IM += q.wm * T;
    }
    return sr * IR * PR(R.mu) + Mie_s * IM * PM(R.mu);
}
const double M709[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                           {-0.9692660, 1.8760108, 0.0415560},
                           {0.0556434, -0.2040259, 1.0572252}};
const double X709[3][3] = {
    {0.4124564, 0.3575761, 0.1804375}, {0.2126729, 0.7151522, 0.0721750}, {0.0193339, 0.1191920, 0.9503041}};
std::array<double, 3> mul(const double m[3][3], std::array<double, 3> a) {
    std::array<double, 3> r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i] += m[i][j] * a[j];
    return r;
}
std::array<double, 2> uv(std::array<double, 3> rgbn) {
    auto X = mul(X709, rgbn);
    double d = X[0] + 15 * X[1] + 3 * X[2];
    return {4 * X[0] / d, 9 * X[1] / d};
}
std::array<double, 3> white() {
    std::array<double, 3> w{};
    for (int i = 0; i < 41; ++i)
        for (int c = 0; c < 3; ++c) w[c] += kCmf[i][c] * kSolar[i + 2] * 10;
    return mul(M709, w);
}
// truth
std::array<double, 3> truthRGB(const Ray& R) {
    std::array<double, 3> X{};
    for (int i = 0; i < 41; ++i) {
        double f = evalF(R, 380 + 10 * i);
        for (int c = 0; c < 3; ++c) X[c] += kCmf[i][c] * kSolar[i + 2] * 10 * f;
    }
    auto r = mul(M709, X);
    auto w = white();
    for (int c = 0; c < 3; ++c) r[c] /= w[c];
    return r;
}
// quadrature with hat weights
std::vector<std::array<double, 3>> hatWeights(const std::vector<double>& nodes) {
    int n = nodes.size();
    std::vector<std::array<double, 3>> W(n);
    for (int i = 0; i < 41; ++i) {
        double lam = 380 + 10 * i;
        std::vector<double> h(n, 0);
        if (lam <= nodes[0])
            h[0] = 1;
        else if (lam >= nodes[n - 1])
            h[n - 1] = 1;
        else
            for (int k = 0; k + 1 < n; ++k)
                if (lam < nodes[k + 1]) {
                    double u = (lam - nodes[k]) / (nodes[k + 1] - nodes[k]);
                    h[k] = 1 - u;
                    h[k + 1] = u;
                    break;
                }
        for (int k = 0; k < n; ++k)
            for (int c = 0; c < 3; ++c) W[k][c] += kCmf[i][c] * kSolar[i + 2] * 10 * h[k];
    }
    return W;
}
std::array<double, 3> quadRGB(const Ray& R, const std::vector<double>& nodes,
                              const std::vector<std::array<double, 3>>& W) {
    std::array<double, 3> X{};
    for (size_t k = 0; k < nodes.size(); ++k) {
        double f = evalF(R, nodes[k]);
        for (int c = 0; c < 3; ++c) X[c] += W[k][c] * f;
    }
    auto r = mul(M709, X);
    auto w = white();
    for (int c = 0; c < 3; ++c) r[c] /= w[c];
    return r;
}
std::array<double, 3> rgbSolverLike(const Ray& R) { return {evalF(R, 680), evalF(R, 550), evalF(R, 440)}; }
double duv(std::array<double, 3> a, std::array<double, 3> b) {
    auto p = uv(a), q = uv(b);
    return std::hypot(p[0] - q[0], p[1] - q[1]);
}
double Y(std::array<double, 3> a) { return 0.2126729 * a[0] + 0.7151522 * a[1] + 0.0721750 * a[2]; }
std::vector<double> solve(std::vector<std::vector<double>> A, std::vector<double> b) {
    int n = b.size();
    for (int i = 0; i < n; ++i) {
        int p = i;
        for (int r = i + 1; r < n; ++r)
            if (std::fabs(A[r][i]) > std::fabs(A[p][i])) p = r;
        std::swap(A[i], A[p]);
        std::swap(b[i], b[p]);
        for (int r = i + 1; r < n; ++r) {
            double f = A[r][i] / A[i][i];
            for (int c = i; c < n; ++c) A[r][c] -= f * A[i][c];
            b[r] -= f * b[i];
        }
    }
    std::vector<double> x(n);
    for (int i = n - 1; i >= 0; --i) {
        double s = b[i];
        for (int c = i + 1; c < n; ++c) s -= A[i][c] * x[c];
        x[i] = s / A[i][i];
    }
    return x;
}
struct TS {
    std::vector<double> f;
    std::array<double, 3> X;
    double Yv;
};
std::array<double, 3> truthXYZ(const Ray& R) {
    std::array<double, 3> X{};
    for (int i = 0; i < 41; ++i) {
        double f = evalF(R, 380 + 10 * i);
        for (int c = 0; c < 3; ++c) X[c] += kCmf[i][c] * kSolar[i + 2] * 10 * f;
    }
    return X;
}
std::array<double, 3> toRGBn(std::array<double, 3> X) {
    auto r = mul(M709, X);
    auto w = white();
    for (int c = 0; c < 3; ++c) r[c] /= w[c];
    return r;
}
int main(int argc, char** argv) {
    std::vector<std::vector<double>> sets;
    for (int a = 1; a < argc; ++a) {
        std::vector<double> s;
        char* p = argv[a];
        while (*p) {
            s.push_back(strtod(p, &p));
            if (*p == ',') ++p;
        }
        sets.push_back(s);
    }
    // training rays
    NV = 300;
    NS = 60;
    std::vector<Ray> train;
    std::vector<double> ozs;
    double tsuns[] = {90, 60,   40, 25,   15, 10,   7,  5,    3,  2,    1,  0.5,  0,  -0.5,
                      -1, -1.5, -2, -2.5, -3, -3.5, -4, -4.5, -5, -5.5, -6, -6.5, -7, -8};
    double tels[] = {0, 1, 2, 3, 5, 8, 12, 20, 35, 60, 90};
    double tazs[] = {0, 20, 45, 70, 90, 120, 150, 180};
    for (double se : tsuns)
        for (double el : tels)
            for (double az : tazs) {
                if (el == 90 && az > 0) continue;
                train.push_back(trace(se * PI / 180, el * PI / 180, az * PI / 180));
            }
    fprintf(stderr, "%zu training rays\n", train.size());
    NV = 1000;
    NS = 200;
    double suns[] = {90, 30, 10, 2, 0, -2, -4, -6};
    struct Dir {
        double el, az;
        const char* n;
    } dirs[] = {{90, 0, "zen"}, {3, 0, "tow"}, {3, 90, "acr"}, {3, 180, "awy"}};
    std::vector<Ray> test;
    for (double se : suns)
        for (auto d : dirs) {
            double el = d.el;
            if (d.az == 180) el = 3 + std::max(0.0, -1.5 * se);
            test.push_back(trace(se * PI / 180, el * PI / 180, d.az * PI / 180));
        }
    double oscales[] = {1.0, 0.6, 1.6};
    for (auto& nodes : sets) {
        int n = nodes.size();
        // build training
        std::vector<TS> T;
        for (double ms : {1.0, 5.0})
            for (double os : oscales) {
                ozScale = os;
                Mie_s = 3.996e-6 * ms;
                Mie_e = Mie_s / 0.9;
                for (auto& R : train) {
                    TS t;
                    for (double l : nodes) t.f.push_back(evalF(R, l));
                    t.X = truthXYZ(R);
                    t.Yv = t.X[1];
                    if (!(t.Yv > 1e-12)) continue;
                    T.push_back(t);
                }
            }
        ozScale = 1;
        Mie_s = 3.996e-6;
        Mie_e = Mie_s / 0.9;
        auto Wh = hatWeights(nodes);
        std::vector<std::array<double, 3>> W(n);
        for (int c = 0; c < 3; ++c) {
            std::vector<std::vector<double>> A(n, std::vector<double>(n, 0));
            std::vector<double> b(n, 0);
            for (auto& t : T) {
                double w = 1 / (t.Yv * t.Yv);
                for (int i = 0; i < n; ++i) {
                    for (int j = 0; j < n; ++j) A[i][j] += w * t.f[i] * t.f[j];
                    b[i] += w * t.f[i] * t.X[c];
                }
            }
            // white constraint heavy; regularise towards hat
            double white = 0;
            for (int i = 0; i < 41; ++i) white += kCmf[i][c] * kSolar[i + 2] * 10;
            double lamW = 1e4 / (white * white) * T.size();
            double reg = 1e-3 * T.size() / (white * white);
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j < n; ++j) A[i][j] += lamW;
                b[i] += lamW * white;
                A[i][i] += reg;
                b[i] += reg * Wh[i][c];
            }
            auto x = solve(A, b);
            for (int i = 0; i < n; ++i) W[i][c] = x[i];
        }
        printf("nodes:");
        for (double l : nodes) printf(" %g", l);
        printf("\n W:");
        for (int i = 0; i < n; ++i) printf("\n {%.9g, %.9g, %.9g},", W[i][0], W[i][1], W[i][2]);
        printf("\n");
        double wh = 0, wf = 0, yh = 0, yf = 0;
        for (double ms : {1.0, 5.0})
            for (double os : oscales) {
                ozScale = os;
                Mie_s = 3.996e-6 * ms;
                Mie_e = Mie_s / 0.9;
                double wh1 = 0, wf1 = 0;
                for (size_t k = 0; k < test.size(); ++k) {
                    auto X = truthXYZ(test[k]);
                    if (!(X[1] > 0)) continue;
                    auto t = toRGBn(X);
                    std::array<double, 3> Xh{}, Xf{};
                    for (int i = 0; i < n; ++i) {
                        double f = evalF(test[k], nodes[i]);
                        for (int c = 0; c < 3; ++c) {
                            Xh[c] += Wh[i][c] * f;
                            Xf[c] += W[i][c] * f;
                        }
                    }
                    auto qh = toRGBn(Xh), qf = toRGBn(Xf);
                    double eh = duv(qh, t), ef = duv(qf, t);
                    wh1 = std::max(wh1, eh);
                    wf1 = std::max(wf1, ef);
                    yh = std::max(yh, std::fabs(Y(qh) / Y(t) - 1));
                    yf = std::max(yf, std::fabs(Y(qf) / Y(t) - 1));
                    if (os == 1 && ms == 1 && argc <= 3)
                        printf("  sun %5.1f dir %zu hat %.4f fit %.4f  Yfit %.4f\n", suns[k / 4], k % 4, eh,
                               ef, Y(qf) / Y(t) - 1);
                }
                printf(" mie %.0f oz %.1f worst hat %.4f fit %.4f\n", ms, os, wh1, wf1);
                wh = std::max(wh, wh1);
                wf = std::max(wf, wf1);
            }
        printf(" worst hat %.4f fit %.4f   Y hat %.4f fit %.4f\n", wh, wf, yh, yf);
    }
}
