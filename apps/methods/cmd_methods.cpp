// cmd_methods.cpp - `ggx methods`: the methods and their traits, a Markdown
// table printed from ggxcl's one table of methods (ggx_contract.h's
// GGX_METHOD_LIST through ggxcl::method_table), with why each missing trait is
// missing.  The README's table of methods is this output (test_readme_methods);
// `--names` lists the names alone, one per line, for scripts.
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <ggxcl/ggxcl.hpp>

#include "commands.hpp"

namespace ggxapp {

namespace {

const char* yes_no(bool value)
{
    return value ? "yes" : "no";
}

std::string methods_markdown()
{
    std::ostringstream md;
    md << "| method | paper | how | space | alpha | normals | dielectric | views below |\n"
       << "|---|---|---|---|---|---|---|---|\n";
    for (const ggxcl::MethodTraits& t : ggxcl::method_table)
        md << "| `" << t.name << "` | " << t.paper << " | " << t.how << " | " << ggxcl::space_name(t.space) << " | "
           << (t.isotropic_only ? "isotropic" : "anisotropic") << " | " << ggxcl::distribution_name(t.normals)
           << " | " << yes_no(t.dielectric) << " | " << yes_no(t.views_below) << " |\n";
    md << "\n";
    for (const ggxcl::MethodTraits& t : ggxcl::method_table)
        if (!t.limits.empty())
            md << "- `" << t.name << "`: " << t.limits << ".\n";
    return md.str();
}

} // namespace

Prepare add_methods_command(CLI::App& app)
{
    CLI::App* cmd = app.add_subcommand(
        "methods", "List the sampling methods and their traits: space, roughness, the normals' distribution, "
                   "dielectrics, views below the horizon");
    auto names = std::make_shared<bool>(false);
    cmd->add_flag("--names", *names, "the methods' names alone, one per line (for scripts)");
    return [cmd, names]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        return Work{[names] {
                        if (!*names)
                            std::cout << methods_markdown();
                        else
                            for (const ggxcl::MethodTraits& t : ggxcl::method_table)
                                std::cout << t.name << "\n";
                    },
                    {}};
    };
}

} // namespace ggxapp
