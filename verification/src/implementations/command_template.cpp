#include "crossdiv/verification/implementations/command_template.h"

#include <algorithm>
#include <array>
#include <filesystem>

#include "crossdiv/error.h"
#include "crossdiv/verification/harness/install_paths.h"

namespace crossdiv::verification {
namespace {

constexpr std::array<std::string_view, 16> kPlaceholders = {"in",      "in.obj",  "in.untagged", "in.off",
                                                            "in.ply",  "out",     "out.obj",     "out.off",
                                                            "out.ply", "levels",  "scheme",      "weights",
                                                            "boundary", "adapters", "dir",        "ops"};

}  // namespace

const char* to_string(MeshFormat format) {
    switch (format) {
        case MeshFormat::Obj: return "obj";
        case MeshFormat::Off: return "off";
        case MeshFormat::Ply: return "ply";
    }
    return "obj";
}

CommandTemplate::CommandTemplate(std::string text, bool needs_output) : text_(std::move(text)) {
    auto fail = [&](const std::string& what) { throw InputError("command '" + text_ + "': " + what); };
    std::vector<Piece> word;
    bool in_word = false;
    auto literal = [&](char c) {
        if (word.empty() || word.back().placeholder) word.push_back({false, ""});
        word.back().text += c;
        in_word = true;
    };
    auto end_word = [&] {
        if (in_word) words_.push_back(std::move(word));
        word.clear();
        in_word = false;
    };
    char quote = 0;
    for (size_t i = 0; i < text_.size(); ++i) {
        const char c = text_[i];
        if (quote == '\'') {
            if (c == '\'') quote = 0;
            else literal(c);
            continue;
        }
        if (c == '\\' && i + 1 < text_.size()) {
            literal(text_[++i]);
            continue;
        }
        if (quote == '"' && c == '"') {
            quote = 0;
            continue;
        }
        if (!quote && (c == '\'' || c == '"')) {
            quote = c;
            in_word = true;  // '' is an empty argument
            continue;
        }
        if (!quote && (c == ' ' || c == '\t' || c == '\n')) {
            end_word();
            continue;
        }
        if (c == '{' && i + 1 < text_.size() && text_[i + 1] == '{') {
            literal('{');
            ++i;
            continue;
        }
        if (c == '}' && i + 1 < text_.size() && text_[i + 1] == '}') {
            literal('}');
            ++i;
            continue;
        }
        if (c == '{') {
            const size_t close = text_.find('}', i);
            if (close == std::string::npos) fail("'{' without '}' at character " + std::to_string(i + 1));
            const std::string name = text_.substr(i + 1, close - i - 1);
            if (std::find(kPlaceholders.begin(), kPlaceholders.end(), name) == kPlaceholders.end())
                fail("unknown placeholder {" + name +
                     "} (known: {in} {in.obj} {in.untagged} {in.off} {in.ply} {out} {out.obj} {out.off} {out.ply} "
                     "{levels} {scheme} {weights} {boundary} {adapters} {dir} {ops})");
            word.push_back({true, name});
            in_word = true;
            i = close;
            continue;
        }
        if (c == '}') fail("'}' without '{' at character " + std::to_string(i + 1) + " (write }} for a brace)");
        literal(c);
    }
    if (quote) fail(std::string("unclosed ") + quote);
    end_word();
    if (words_.empty()) fail("no program");

    int outputs = 0;
    bool obj_out = false, off_out = false, ply_out = false;
    for (const auto& w : words_)
        for (const Piece& p : w) {
            if (!p.placeholder) continue;
            reads_obj_ |= p.text == "in" || p.text == "in.obj";
            reads_untagged_ |= p.text == "in.untagged";
            reads_off_ |= p.text == "in.off";
            reads_ply_ |= p.text == "in.ply";
            obj_out |= p.text == "out" || p.text == "out.obj";
            off_out |= p.text == "out.off";
            ply_out |= p.text == "out.ply";
            outputs += p.text.starts_with("out");
        }
    if (outputs == 0 && needs_output) fail("no {out}: the command must be told where to write its result");
    if (obj_out + off_out + ply_out > 1) fail("more than one output format; name one of {out} {out.off} {out.ply}");
    output_format_ = off_out ? MeshFormat::Off : ply_out ? MeshFormat::Ply : MeshFormat::Obj;
}

void CommandTemplate::anchor_relative_paths(const std::string& base) {
    namespace fs = std::filesystem;
    for (auto& w : words_) {
        if (w.size() != 1 || w[0].placeholder || w[0].text.empty() || w[0].text[0] == '/') continue;
        std::error_code ec;
        const fs::path p = base.empty() ? fs::path(w[0].text) : fs::path(base) / w[0].text;
        if (fs::exists(p, ec)) w[0].text = fs::absolute(p, ec).lexically_normal().string();
    }
}

std::string CommandTemplate::anchored_text() const {
    std::string text;
    for (const auto& w : words_) {
        if (!text.empty()) text += ' ';
        for (const Piece& p : w) text += p.placeholder ? "{" + p.text + "}" : p.text;
    }
    return text;
}

bool CommandTemplate::reads_tags() const { return reads_obj_; }

bool CommandTemplate::reads_untagged_obj() const { return reads_untagged_; }

bool CommandTemplate::reads(MeshFormat format) const {
    switch (format) {
        case MeshFormat::Obj: return reads_obj_;
        case MeshFormat::Off: return reads_off_;
        case MeshFormat::Ply: return reads_ply_;
    }
    return false;
}

std::vector<std::string> CommandTemplate::expand(const TemplateValues& v) const {
    std::vector<std::string> argv;
    for (const auto& w : words_) {
        std::string arg;
        for (const Piece& p : w) {
            if (!p.placeholder) arg += p.text;
            else if (p.text == "in" || p.text == "in.obj") arg += v.in_obj;
            else if (p.text == "in.untagged") arg += v.in_untagged;
            else if (p.text == "in.off") arg += v.in_off;
            else if (p.text == "in.ply") arg += v.in_ply;
            else if (p.text == "adapters") arg += adapters_dir();
            else if (p.text == "dir") arg += v.dir;
            else if (p.text == "ops") arg += v.ops;
            else if (p.text.starts_with("out")) arg += v.out;
            else if (p.text == "levels") arg += std::to_string(v.request.levels);
            else if (p.text == "scheme") arg += to_string(v.request.scheme);
            else if (p.text == "weights") arg += to_string(v.request.rule.loop.weights);
            else if (p.text == "boundary") arg += boundary_name(v.request.scheme, v.request.rule);
        }
        argv.push_back(std::move(arg));
    }
    return argv;
}

size_t CommandTemplate::shared_words(const CommandTemplate& other) const {
    size_t n = 0;
    while (n < words_.size() && n < other.words_.size() && words_[n] == other.words_[n]) ++n;
    return n;
}

bool CommandTemplate::names_run_values() const {
    for (const auto& w : words_)
        for (const Piece& p : w)
            if (p.placeholder && p.text != "adapters" && p.text != "dir") return true;
    return false;
}

}  // namespace crossdiv::verification
