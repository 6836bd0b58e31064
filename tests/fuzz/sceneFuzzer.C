// libFuzzer target for the scene reader (tests/fuzz/runSceneFuzzer): the input,
// split at its first NUL byte, is a constant/sceneProperties and a
// system/controlDict. Anything may be refused with an InputError; nothing may
// crash, hang, leak or trip AddressSanitizer / UndefinedBehaviorSanitizer.
#include "dictionary.H"
#include "scene.H"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t cut = input.find('\0');
    const std::string sceneText = input.substr(0, cut);
    const std::string controlText = cut == std::string::npos
        ? std::string("endTime 1;\nwriteInterval 0.1;\n") : input.substr(cut + 1);
    try
    {
        using namespace slide::scene;
        const Dictionary d = Dictionary::parse(sceneText, "constant/sceneProperties");
        const Dictionary c = Dictionary::parse(controlText, "system/controlDict");
        const Scene sc = Scene::fromDictionaries(d, c, "fuzz");
        // Touch what the methods use first, so that a bad but accepted value shows.
        volatile double a = sc.slide.area() + sc.slide.thickness(0.5*sc.slide.length) + sc.interface.basalStrength(1.0);
        (void)a;
        (void)sc.describe();
    }
    catch (const slide::scene::InputError&)
    {
    }
    return 0;
}
