// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "file_output.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace tripose_samples {

std::string temporaryNameFor(const std::string& path)
{
    // Keep the extension: FileStorage picks YAML or JSON from it.
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return path + ".partial";
    return path.substr(0, dot) + ".partial" + path.substr(dot);
}

void commitAtomicWrite(const std::string& temporary, const std::string& path)
{
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
    {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write " + path);
    }
}

void checkWritable(const std::string& path, const std::string& option)
{
    if (path.empty())
        return;
    std::error_code error;
    const std::filesystem::path file(path);
    const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
    std::string reason;
    if (!std::filesystem::is_directory(folder, error))
        reason = "no folder " + folder.string();
    else if (std::filesystem::is_directory(file, error))
        reason = "a folder of that name exists";
    else
    {
        const std::string temporary = temporaryNameFor(path);
        if (std::ofstream(temporary, std::ios::binary))
            std::remove(temporary.c_str());
        else
            reason = "no file can be created in " + folder.string();
    }
    if (!reason.empty())
        throw std::runtime_error(option + " " + path + ": cannot be written (" + reason + ")");
}

void writeFileAtomically(const std::string& path, const std::vector<unsigned char>& bytes)
{
    const std::string temporary = temporaryNameFor(path);
    {
        std::ofstream out(temporary, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()), (std::streamsize)bytes.size());
        if (!out)
        {
            out.close();
            std::remove(temporary.c_str());
            throw std::runtime_error("cannot write " + path);
        }
    }
    commitAtomicWrite(temporary, path);
}

} // namespace tripose_samples
