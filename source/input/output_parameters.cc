#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fourier_ssi/input/boundary_conditions.h>
#include <fourier_ssi/input/output_parameters.h>
#include <fstream>
#include <iterator>
#include <sstream>

namespace FourierSSI
{
  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Where results go (created if missing). The value "
                      "is taken literally: not empty, no quotes; the folder "
                      "(or its nearest existing parent) must be writable, "
                      "checked before the run. A relative path is relative "
                      "to the folder the program runs in (Mesh/Mesh file, "
                      "unlike it, is relative to the .prm file's folder).");
    prm.declare_entry("Results file",
                      "results.csv",
                      Patterns::FileName(),
                      "CSV of scalar results: one row per quantity, harmonic "
                      "and cycle, with units.");
    prm.declare_entry("Write vtu",
                      "true",
                      Patterns::Bool(),
                      "Write the displacement amplitudes of each harmonic "
                      "as VTU (solution-n<n>-<family>-cycle<c>.vtu); with a "
                      "coulomb interface or plastic soil those of the last "
                      "converged step, with plastic soil without stresses "
                      "(doc/output-files.md).");
    prm.declare_entry("Write stresses",
                      "true",
                      Patterns::Bool(),
                      "Add the six stress amplitudes to the VTU (stress "
                      "recovery is skipped otherwise).");
    prm.declare_entry("Write interface tractions",
                      "true",
                      Patterns::Bool(),
                      "Write relative displacements and tractions per "
                      "interface node pair (CSV per interface and harmonic).");
    prm.declare_entry("Lines 3D",
                      "",
                      Patterns::Anything(),
                      "3D reconstruction (sum of the harmonics) along "
                      "straight lines: 'r0, z0 -> r1, z1 : points; ...'; "
                      "written to lines-3d.csv at the angles below. At most "
                      "100000 points per line, every point inside the mesh "
                      "(both checked before the solve).");
    prm.declare_entry("Theta values",
                      "0",
                      Patterns::List(Patterns::Double()),
                      "Angles [degrees] of the Lines 3D output.");
    prm.declare_entry("Write 3D vtu",
                      "false",
                      Patterns::Bool(),
                      "Write the mesh revolved about the axis with the 3D "
                      "displacement (solution-3d.vtu, for ParaView).");
    prm.declare_entry("Theta divisions",
                      "36",
                      Patterns::Integer(3, 720),
                      "Sectors of the revolved 3D VTU (solution-3d.vtu, "
                      "and plastic-field-3d-step<s>.vtu of plastic soil).");
    prm.declare_entry("Soil reaction depths",
                      "",
                      Patterns::Anything(),
                      "Soil-reaction curves of a pile in plastic soil "
                      "(PISA: p-v, m-psi, base H_B-v and M_B-psi, one point "
                      "per load step) at these depths [m below the pile's "
                      "head], or 'auto' (10 evenly spaced) or 'auto N'; "
                      "written to soil-reaction-curves.csv "
                      "(doc/soil-reaction-curves.md). Empty: none.");
    prm.declare_entry("Soil reaction pile",
                      "auto",
                      Patterns::Anything(),
                      "The material id of the pile whose soil-reaction "
                      "curves are written: a solid or hollow (tube) pile, "
                      "rigid or an elastic material region loaded through "
                      "the Rigid foundation's tied material. auto: the "
                      "Rigid foundation's Id (a rigid pile).");
    prm.declare_entry("Plastic field steps",
                      "last",
                      Patterns::Anything(),
                      "Plastic soil: the load steps (numbers as in "
                      "load-displacement.csv, from 1) whose plastic field "
                      "is written (plastic strain, yield state, stress, "
                      "displacement; doc/output-files.md), or 'last'. "
                      "Steps beyond the path stop the run at its end, "
                      "before any result is written.");
    prm.declare_entry("Plastic field planes",
                      "0, 90",
                      Patterns::Anything(),
                      "Plastic soil: meridian planes [degrees, 0 <= theta "
                      "< 360] written as plastic-field-theta<deg>-step<s>."
                      "vtu, each at the nearest theta sample of the soil; "
                      "empty: none. Needs Write vtu.");
    prm.declare_entry("Plastic field 3D",
                      "false",
                      Patterns::Bool(),
                      "Plastic soil: the soil cells revolved about the axis "
                      "in Theta divisions sectors with the plastic field "
                      "(plastic-field-3d-step<s>.vtu). Needs Write vtu.");
    prm.declare_entry("Interface state 3D",
                      "false",
                      Patterns::Bool(),
                      "Nonlinear (coulomb, contact) interfaces: their state "
                      "as a surface revolved about the axis, one quad per "
                      "interface point and theta sample with its stick / "
                      "slip / open state, tractions and relative "
                      "displacements (interface-state-3d-step<s>.vtu and "
                      "interface-state-3d.pvd; doc/output-files.md). "
                      "Refused without a nonlinear interface.");
    prm.declare_entry("Interface state steps",
                      "last",
                      Patterns::Anything(),
                      "The load steps (as in load-displacement.csv, from 1) "
                      "written by Interface state 3D, or 'last'. Steps "
                      "beyond the path stop the run at its end, before any "
                      "result is written.");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse_soil_reaction_depths(const std::string &text)
  {
    const auto fail = [&]() {
      AssertThrow(false,
                  ExcMessage("Output/Soil reaction depths: '" + text +
                             "' is not a list of depths >= 0 [m], 'auto' or "
                             "'auto N' (N from 1 to 1000)"));
    };
    soil_reaction_depths.clear();
    soil_reaction_auto = 0;
    const auto words   = Utilities::split_string_list(text, ' ');
    if (!words.empty() && words[0] == "auto")
      {
        if (words.size() > 2)
          fail();
        try
          {
            soil_reaction_auto =
              words.size() == 1 ? 10 : Utilities::string_to_int(words[1]);
          }
        catch (...)
          {
            fail();
          }
        if (soil_reaction_auto < 1 || soil_reaction_auto > 1000)
          fail();
        return;
      }
    try
      {
        for (const std::string &d : Utilities::split_string_list(text))
          soil_reaction_depths.push_back(Utilities::string_to_double(d));
      }
    catch (...)
      {
        fail();
      }
    for (const double d : soil_reaction_depths)
      if (!(d >= 0.) || !std::isfinite(d))
        fail();
  }

  void
  OutputParameters::parse_soil_reaction_pile(const std::string &text)
  {
    soil_reaction_pile = -1;
    if (text == "auto")
      return;
    const std::string message = "Output/Soil reaction pile: '" + text +
                                "' is not 'auto' or a material id (0 to 255)";
    try
      {
        soil_reaction_pile = Utilities::string_to_int(text);
      }
    catch (...)
      {
        AssertThrow(false, ExcMessage(message));
      }
    AssertThrow(soil_reaction_pile >= 0 && soil_reaction_pile <= 255,
                ExcMessage(message));
  }

  void
  OutputParameters::parse_plastic_field_steps(const std::string &text)
  {
    plastic_field_steps = parse_load_steps("Plastic field steps", text);
  }

  std::vector<unsigned int>
  OutputParameters::parse_load_steps(const std::string &entry,
                                     const std::string &text)
  {
    std::vector<unsigned int> steps;
    if (Utilities::trim(text) == "last")
      return steps;
    const std::string message =
      "Output/" + entry + ": '" + text +
      "' is not 'last' or a list of load step numbers (1, 2, ...) in "
      "increasing order, each once";
    const auto words = Utilities::split_string_list(text);
    AssertThrow(!words.empty(), ExcMessage(message));
    for (const std::string &word : words)
      {
        // Whole numbers only: string_to_int would read "2.5" as 2.
        AssertThrow(!word.empty() &&
                      word.find_first_not_of("0123456789") == std::string::npos,
                    ExcMessage(message));
        unsigned long step = 0;
        try
          {
            step = std::stoul(word);
          }
        catch (...)
          {
            AssertThrow(false, ExcMessage(message));
          }
        AssertThrow(step >= 1 && step <= 1000000 &&
                      (steps.empty() || step > steps.back()),
                    ExcMessage(message));
        steps.push_back(static_cast<unsigned int>(step));
      }
    return steps;
  }

  void
  OutputParameters::parse_plastic_field_planes(const std::string &text)
  {
    plastic_field_planes.clear();
    const std::string message =
      "Output/Plastic field planes: '" + text +
      "' is not a list of angles theta [degrees] with 0 <= theta < 360, "
      "each once";
    for (const std::string &word : Utilities::split_string_list(text))
      {
        double theta = 0.;
        try
          {
            theta = Utilities::string_to_double(word);
          }
        catch (...)
          {
            AssertThrow(false, ExcMessage(message));
          }
        AssertThrow(std::isfinite(theta) && theta >= 0. && theta < 360. &&
                      std::find(plastic_field_planes.begin(),
                                plastic_field_planes.end(),
                                theta) == plastic_field_planes.end(),
                    ExcMessage(message));
        plastic_field_planes.push_back(theta);
      }
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory                 = prm.get("Directory");
    results_file              = prm.get("Results file");
    write_vtu                 = prm.get_bool("Write vtu");
    write_stresses            = prm.get_bool("Write stresses");
    write_interface_tractions = prm.get_bool("Write interface tractions");
    write_3d_vtu              = prm.get_bool("Write 3D vtu");
    theta_divisions           = prm.get_integer("Theta divisions");
    theta_degrees.clear();
    for (const std::string &t :
         Utilities::split_string_list(prm.get("Theta values")))
      theta_degrees.push_back(Utilities::string_to_double(t));
    parse_soil_reaction_depths(prm.get("Soil reaction depths"));
    parse_soil_reaction_pile(prm.get("Soil reaction pile"));
    parse_plastic_field_steps(prm.get("Plastic field steps"));
    parse_plastic_field_planes(prm.get("Plastic field planes"));
    plastic_field_3d      = prm.get_bool("Plastic field 3D");
    interface_state_3d    = prm.get_bool("Interface state 3D");
    interface_state_steps = parse_load_steps("Interface state steps",
                                             prm.get("Interface state steps"));
    lines.clear();
    for (const std::string &item : split_top_level(prm.get("Lines 3D"), ';'))
      {
        const auto fail = [&]() {
          AssertThrow(false,
                      ExcMessage("Output/Lines 3D: '" + item +
                                 "' is not 'r0, z0 -> r1, z1 : points'"));
        };
        const auto arrow = item.find("->");
        const auto colon = item.find(':');
        if (arrow == std::string::npos || colon == std::string::npos ||
            colon < arrow)
          fail();
        OutputLine line;
        try
          {
            const auto a = Utilities::split_string_list(item.substr(0, arrow));
            const auto b = Utilities::split_string_list(
              item.substr(arrow + 2, colon - arrow - 2));
            if (a.size() != 2 || b.size() != 2)
              fail();
            line.start = Point<2>(Utilities::string_to_double(a[0]),
                                  Utilities::string_to_double(a[1]));
            line.end   = Point<2>(Utilities::string_to_double(b[0]),
                                Utilities::string_to_double(b[1]));
            line.n_points =
              Utilities::string_to_int(Utilities::trim(item.substr(colon + 1)));
          }
        catch (...)
          {
            fail();
          }
        if (line.n_points < 1)
          fail();
        AssertThrow(line.n_points <= max_points_per_line,
                    ExcMessage("Output/Lines 3D: '" + item + "' asks for " +
                               std::to_string(line.n_points) +
                               " points, above the limit of " +
                               std::to_string(max_points_per_line) +
                               " points per line"));
        lines.push_back(line);
      }
    check_lines_3d_size();
    prm.leave_subsection();
  }

  void
  OutputParameters::check_lines_3d_size() const
  {
    std::size_t rows = 0;
    for (const OutputLine &line : lines)
      rows += std::size_t(line.n_points) * theta_degrees.size();
    // About 213 bytes a row (measured on prm/default.prm's stresses).
    AssertThrow(rows <= max_lines_3d_rows,
                ExcMessage("Output/Lines 3D: " + std::to_string(rows) +
                           " rows (points times the " +
                           std::to_string(theta_degrees.size()) +
                           " Theta values) would make lines-3d.csv about " +
                           std::to_string(rows * 213 / 1000000) +
                           " MB; at most " + std::to_string(max_lines_3d_rows) +
                           " rows (about 213 MB): fewer points or angles"));
  }

  namespace
  {
    /**
     * The text of a parameter file as a light scan reads it: NUL bytes
     * dropped (a UTF-16 file is ASCII with a NUL after every character),
     * byte-order marks and carriage returns dropped, lines ending in a
     * backslash joined to the next, comments cut.
     */
    std::vector<std::string>
    scanned_lines(const std::string &prm_file)
    {
      std::ifstream in(prm_file, std::ios::binary);
      std::string   raw((std::istreambuf_iterator<char>(in)),
                      std::istreambuf_iterator<char>());
      raw.erase(std::remove_if(raw.begin(),
                               raw.end(),
                               [](const char c) {
                                 const auto b = static_cast<unsigned char>(c);
                                 return b == 0 || b == '\r' || b == 0xFE ||
                                        b == 0xFF;
                               }),
                raw.end());
      const std::string byte_order_mark = "\xEF\xBB\xBF"; // UTF-8's
      if (raw.compare(0, byte_order_mark.size(), byte_order_mark) == 0)
        raw.erase(0, byte_order_mark.size());
      std::vector<std::string> lines;
      std::istringstream       text(raw);
      std::string              line, joined;
      while (std::getline(text, line))
        {
          line = line.substr(0, line.find('#'));
          if (!line.empty() && line.back() == '\\')
            {
              joined += line.substr(0, line.size() - 1);
              continue;
            }
          lines.push_back(joined + line);
          joined.clear();
        }
      lines.push_back(joined);
      return lines;
    }
  } // namespace

  std::optional<OutputParameters>
  OutputParameters::read_folder_of(const std::string &prm_file)
  {
    std::error_code ignored;
    if (!std::filesystem::is_regular_file(prm_file, ignored))
      return std::nullopt;
    // Not ParameterHandler: the folder must be found in the very files it
    // refuses (a missing or extra end, a set without '=', a NUL byte, a
    // UTF-16 file), so that their run removes the last run's results.
    OutputParameters         output;
    std::vector<std::string> subsections;
    for (const std::string &line : scanned_lines(prm_file))
      {
        std::istringstream words(line);
        std::string        word;
        words >> word;
        const std::streamoff position = words.tellg();
        const std::size_t    after_word =
          position < 0 ? line.size() : static_cast<std::size_t>(position);
        std::transform(word.begin(), word.end(), word.begin(), [](char c) {
          return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        });
        if (word == "end" && !subsections.empty())
          subsections.pop_back();
        if (word == "subsection")
          subsections.push_back(Utilities::trim(line.substr(after_word)));
        const std::size_t equals = line.find('=');
        if (word != "set" || equals == std::string::npos ||
            subsections != std::vector<std::string>{"Output"})
          continue;
        const std::string key =
          Utilities::trim(line.substr(after_word, equals - after_word));
        const std::string value = Utilities::trim(line.substr(equals + 1));
        if (key == "Directory")
          output.directory = value;
        else if (key == "Results file")
          output.results_file = value;
      }
    return output;
  }
} // namespace FourierSSI
