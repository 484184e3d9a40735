// Loop subdivision as a standalone C++ program, written the way a course student writes it
// from the assignment text: an edge table in a std::map, odd vertices 3/8, 3/8, 1/8, 1/8,
// even vertices with Loop's original beta, (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n. Boundary
// edges take the midpoint; boundary vertices are left where they are (a common reading of
// "keep the boundary"), which no named Loop rule does.
//
//   loop IN.obj LEVELS OUT.obj
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using Vec = std::array<double, 3>;
using Tri = std::array<int, 3>;

static Vec operator+(Vec a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
static Vec operator*(double s, const Vec& a) { return {s * a[0], s * a[1], s * a[2]}; }

static bool read_obj(const char* path, std::vector<Vec>& v, std::vector<Tri>& f) {
    std::ifstream in(path);
    if (!in) return false;
    for (std::string line; std::getline(in, line);) {
        std::istringstream ss(line);
        std::string tag;
        ss >> tag;
        if (tag == "v") {
            Vec p{};
            ss >> p[0] >> p[1] >> p[2];
            v.push_back(p);
        } else if (tag == "f") {
            Tri t{};
            for (int& i : t) {
                std::string w;
                ss >> w;
                i = std::stoi(w.substr(0, w.find('/'))) - 1;
            }
            f.push_back(t);
        }
    }
    return true;
}

static void subdivide(std::vector<Vec>& v, std::vector<Tri>& f) {
    std::map<std::pair<int, int>, std::vector<int>> edge_faces;  // edge -> opposite corners
    for (const Tri& t : f)
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            edge_faces[{std::min(a, b), std::max(a, b)}].push_back(t[(k + 2) % 3]);
        }
    std::vector<std::set<int>> ring(v.size());
    std::vector<bool> on_boundary(v.size(), false);
    for (const auto& [e, opp] : edge_faces) {
        ring[e.first].insert(e.second);
        ring[e.second].insert(e.first);
        if (opp.size() == 1) on_boundary[e.first] = on_boundary[e.second] = true;
    }
    std::vector<Vec> out(v.size());
    std::map<std::pair<int, int>, int> edge_vertex;
    for (const auto& [e, opp] : edge_faces) {
        edge_vertex[e] = static_cast<int>(out.size());
        if (opp.size() == 2)
            out.push_back(3.0 / 8.0 * (v[e.first] + v[e.second]) + 1.0 / 8.0 * (v[opp[0]] + v[opp[1]]));
        else
            out.push_back(0.5 * (v[e.first] + v[e.second]));
    }
    for (size_t i = 0; i < v.size(); ++i) {
        const double n = static_cast<double>(ring[i].size());
        if (on_boundary[i] || n == 0) {
            out[i] = v[i];
            continue;
        }
        const double c = 3.0 / 8.0 + std::cos(2.0 * M_PI / n) / 4.0;
        const double beta = (5.0 / 8.0 - c * c) / n;
        Vec sum{};
        for (int j : ring[i]) sum = sum + v[j];
        out[i] = (1.0 - n * beta) * v[i] + beta * sum;
    }
    std::vector<Tri> faces;
    for (const Tri& t : f) {
        int m[3];
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            m[k] = edge_vertex[{std::min(a, b), std::max(a, b)}];
        }
        faces.push_back({t[0], m[0], m[2]});
        faces.push_back({t[1], m[1], m[0]});
        faces.push_back({t[2], m[2], m[1]});
        faces.push_back({m[0], m[1], m[2]});
    }
    v = std::move(out);
    f = std::move(faces);
}

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: loop IN.obj LEVELS OUT.obj\n";
        return 2;
    }
    std::vector<Vec> v;
    std::vector<Tri> f;
    if (!read_obj(argv[1], v, f)) {
        std::cerr << "cannot read " << argv[1] << "\n";
        return 1;
    }
    for (int l = std::atoi(argv[2]); l > 0; --l) subdivide(v, f);
    std::FILE* out = std::fopen(argv[3], "w");
    if (!out) return 1;
    for (const Vec& p : v) std::fprintf(out, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    for (const Tri& t : f) std::fprintf(out, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
    return std::fclose(out) == 0 ? 0 : 1;
}
