#include <deal.II/base/exceptions.h>
#include <filesystem>
#include <fourier_ssi/input/atomic_file.h>

namespace FourierSSI
{
  namespace
  {
    void
    cannot_write(const std::string &name)
    {
      AssertThrow(false,
                  dealii::ExcMessage("Output: cannot write '" + name + "'"));
    }
  } // namespace

  std::string
  AtomicFile::temporary_name(const std::string &name)
  {
    const std::filesystem::path path(name);
    return (path.parent_path() / ("." + path.filename().string() + ".partial"))
      .string();
  }

  AtomicFile::AtomicFile(const std::string &name)
    : name(name)
    , temporary(temporary_name(name))
    , out(temporary, std::ios::out | std::ios::trunc | std::ios::binary)
  {
    if (!out)
      cannot_write(name);
  }

  AtomicFile::~AtomicFile()
  {
    if (committed)
      return;
    out.close();
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
  }

  void
  AtomicFile::commit()
  {
    out.flush();
    const bool complete = static_cast<bool>(out);
    out.close();
    std::error_code error;
    if (complete && !out.fail())
      std::filesystem::rename(temporary, name, error);
    if (!complete || out.fail() || error)
      {
        std::filesystem::remove(temporary, error);
        cannot_write(name);
      }
    committed = true;
  }
} // namespace FourierSSI
