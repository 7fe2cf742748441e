using System;
using System.Collections.Generic;
using System.IO;
using System.Reflection;
using System.Text.RegularExpressions;

namespace Weft.Tests
{
    /// <summary>
    /// Keeps the wrapper from falling behind the C ABI: every function
    /// declared in include/weft.h has a DllImport of the same name and
    /// parameter count in NativeMethods, and no DllImport names a function
    /// the header lacks.
    /// </summary>
    public static class HeaderTests
    {
        private static Runner t;

        public static void Register(Runner runner)
        {
            t = runner;
            t.Run("every header function has a DllImport with its parameter count", EveryFunctionImported);
        }

        /// <summary>The header's functions and their parameter counts, comments removed.</summary>
        internal static Dictionary<string, int> HeaderFunctions(string header)
        {
            string code = Regex.Replace(header, @"/\*.*?\*/", " ", RegexOptions.Singleline);
            code = Regex.Replace(code, @"//[^\n]*", " ");
            var functions = new Dictionary<string, int>();
            foreach (Match m in Regex.Matches(code, @"\b(weft_\w+)\s*\(([^()]*)\)\s*;"))
            {
                string parameters = m.Groups[2].Value.Trim();
                int count = parameters.Length == 0 || parameters == "void" ? 0 : parameters.Split(',').Length;
                functions[m.Groups[1].Value] = count;
            }
            return functions;
        }

        private static string HeaderPath()
        {
            string path = Environment.GetEnvironmentVariable("WEFT_HEADER");
            if (!string.IsNullOrEmpty(path)) return path;
            // dotnet/build/Weft.Tests.exe → include/weft.h
            string dir = Path.GetDirectoryName(typeof(HeaderTests).Assembly.Location);
            return Path.Combine(Path.Combine(Path.Combine(Path.Combine(dir, ".."), ".."), "include"), "weft.h");
        }

        private static void EveryFunctionImported()
        {
            string path = HeaderPath();
            t.True(File.Exists(path), "the header at " + path);
            if (!File.Exists(path)) return;
            Dictionary<string, int> header = HeaderFunctions(File.ReadAllText(path));
            t.True(header.Count >= 70, "at least 70 functions parsed from the header, got " + header.Count);

            Type native = typeof(WeftMesh).Assembly.GetType("Weft.NativeMethods", true);
            var imports = new Dictionary<string, int>();
            foreach (MethodInfo m in native.GetMethods(BindingFlags.Static | BindingFlags.NonPublic | BindingFlags.Public))
            {
                if ((m.Attributes & MethodAttributes.PinvokeImpl) != 0)
                {
                    imports[m.Name] = m.GetParameters().Length;
                }
            }
            var missing = new List<string>();
            foreach (KeyValuePair<string, int> f in header)
            {
                int count;
                if (!imports.TryGetValue(f.Key, out count)) missing.Add(f.Key);
                else t.Equal(f.Value, count, f.Key + " parameter count");
            }
            t.True(missing.Count == 0, "a DllImport for every header function; missing: " + string.Join(", ", missing.ToArray()));
            var stale = new List<string>();
            foreach (string name in imports.Keys)
            {
                if (!header.ContainsKey(name)) stale.Add(name);
            }
            t.True(stale.Count == 0, "no DllImport without a header function; stale: " + string.Join(", ", stale.ToArray()));

            // The parser itself finds a missing import: a declaration the wrapper lacks is reported.
            Dictionary<string, int> probe = HeaderFunctions("/* weft_in_comment(int a); */\nWeftStatus weft_not_there(const double *a, size_t b);\nconst char *weft_version(void);");
            t.Equal(2, probe.Count, "functions in the probe header");
            t.True(probe.ContainsKey("weft_not_there") && !imports.ContainsKey("weft_not_there"), "the probe's function is reported missing");
            t.Equal(0, probe["weft_version"], "(void) counts no parameters");
        }
    }
}
