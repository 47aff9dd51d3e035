#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/messages.h>
#include <sstream>

namespace FourierSSI
{
  std::string
  one_line_message(const std::exception &e)
  {
    // deal.II exceptions carry file/line boilerplate; the user needs only the
    // message, which ExcMessage prints after "Additional information:".
    const std::string text = e.what();
    const auto        info = text.find("Additional information:");
    std::string       body =
      info == std::string::npos ? text : text.substr(info + 23);
    const auto stack = body.find("Stacktrace:");
    if (stack != std::string::npos)
      body = body.substr(0, stack);
    std::istringstream in(body);
    std::string        line, result;
    while (std::getline(in, line))
      {
        line = dealii::Utilities::trim(line);
        if (line.empty() || line.rfind("----", 0) == 0)
          continue;
        result += (result.empty() ? "" : " ") + line;
      }
    return result;
  }
} // namespace FourierSSI
