using System;
using System.Collections.Generic;

namespace Weft.Tests
{
    /// <summary>
    /// A small self-checking test runner: each test is a method; a test fails
    /// when one of its checks fails or it throws. The last line printed is
    /// exactly "N passed, N failed"; the exit code is 1 on any failure.
    /// </summary>
    public sealed class Runner
    {
        private readonly List<string> failures = new List<string>();
        private int passed;
        private int failed;
        private string current;
        private bool currentFailed;

        /// <summary>Runs one named test.</summary>
        public void Run(string name, Action test)
        {
            current = name;
            currentFailed = false;
            try
            {
                test();
            }
            catch (Exception e)
            {
                Fail("threw " + e.GetType().Name + ": " + e.Message);
            }
            if (currentFailed)
            {
                failed++;
                Console.WriteLine("FAIL " + name);
            }
            else
            {
                passed++;
                Console.WriteLine("ok   " + name);
            }
        }

        /// <summary>Records a failed check of the current test.</summary>
        public void Fail(string what)
        {
            currentFailed = true;
            failures.Add(current + ": " + what);
            Console.WriteLine("  " + what);
        }

        /// <summary>Checks a condition.</summary>
        public void True(bool condition, string what)
        {
            if (!condition) Fail("expected " + what);
        }

        /// <summary>Checks a condition is false.</summary>
        public void False(bool condition, string what)
        {
            if (condition) Fail("expected not " + what);
        }

        /// <summary>Checks two values are equal.</summary>
        public void Equal<T>(T expected, T actual, string what)
        {
            if (!EqualityComparer<T>.Default.Equals(expected, actual))
            {
                Fail(what + ": expected " + expected + ", got " + actual);
            }
        }

        /// <summary>Checks two arrays are equal element for element.</summary>
        public void Sequence<T>(T[] expected, T[] actual, string what)
        {
            if (actual == null || expected.Length != actual.Length)
            {
                Fail(what + ": expected " + expected.Length + " elements, got " + (actual == null ? "null" : actual.Length.ToString()));
                return;
            }
            for (int i = 0; i < expected.Length; i++)
            {
                if (!EqualityComparer<T>.Default.Equals(expected[i], actual[i]))
                {
                    Fail(what + "[" + i + "]: expected " + expected[i] + ", got " + actual[i]);
                    return;
                }
            }
        }

        /// <summary>Checks that <paramref name="action"/> throws exactly <typeparamref name="TException"/> and returns it.</summary>
        public TException Throws<TException>(Action action, string what) where TException : Exception
        {
            try
            {
                action();
            }
            catch (TException e)
            {
                return e;
            }
            catch (Exception e)
            {
                Fail(what + ": expected " + typeof(TException).Name + ", got " + e.GetType().Name + ": " + e.Message);
                return null;
            }
            Fail(what + ": expected " + typeof(TException).Name + ", nothing was thrown");
            return null;
        }

        /// <summary>
        /// The body of a test program's Main: runs the tests each group registers, in order,
        /// on one runner, then prints the summary line and returns the exit code.
        /// </summary>
        public static int RunAll(params Action<Runner>[] groups)
        {
            var runner = new Runner();
            foreach (Action<Runner> register in groups) register(runner);
            return runner.Finish();
        }

        /// <summary>Prints the summary line and returns the exit code.</summary>
        public int Finish()
        {
            if (failures.Count > 0)
            {
                Console.WriteLine("failures:");
                foreach (string f in failures) Console.WriteLine("  " + f);
            }
            Console.WriteLine(passed + " passed, " + failed + " failed");
            return failed == 0 ? 0 : 1;
        }
    }
}
