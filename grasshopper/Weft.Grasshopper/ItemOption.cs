using System;
using Grasshopper.Kernel;

namespace Weft.Grasshopper
{
    /// <summary>
    /// An item input declared as data: name, nickname, description and default, so a
    /// component can list its options in a table and the default is written once,
    /// for registering and for reading.
    /// </summary>
    public sealed class ItemOption<T>
    {
        public readonly string Name, Nickname, Description;
        public readonly T Default;
        private readonly Func<GH_Component.GH_InputParamManager, ItemOption<T>, int> register;

        internal ItemOption(string name, string nickname, string description, T fallback,
                            Func<GH_Component.GH_InputParamManager, ItemOption<T>, int> register)
        {
            Name = name;
            Nickname = nickname;
            Description = description;
            Default = fallback;
            this.register = register;
        }

        /// <summary>Adds the input; returns its index.</summary>
        public int Register(GH_Component.GH_InputParamManager pManager)
        {
            return register(pManager, this);
        }

        /// <summary>The input's value at <paramref name="index"/>, or the default when it is empty.</summary>
        public T Read(IGH_DataAccess DA, int index)
        {
            T value = Default;
            DA.GetData(index, ref value);
            return value;
        }
    }

    /// <summary>Makes the <see cref="ItemOption{T}"/> of each kind of item input.</summary>
    public static class ItemOption
    {
        public static ItemOption<double> Number(string name, string nickname, string description, double fallback)
        {
            return new ItemOption<double>(name, nickname, description, fallback,
                (pManager, o) => pManager.AddNumberParameter(o.Name, o.Nickname, o.Description, GH_ParamAccess.item, o.Default));
        }

        public static ItemOption<int> Integer(string name, string nickname, string description, int fallback)
        {
            return new ItemOption<int>(name, nickname, description, fallback,
                (pManager, o) => pManager.AddIntegerParameter(o.Name, o.Nickname, o.Description, GH_ParamAccess.item, o.Default));
        }

        public static ItemOption<bool> Boolean(string name, string nickname, string description, bool fallback)
        {
            return new ItemOption<bool>(name, nickname, description, fallback,
                (pManager, o) => pManager.AddBooleanParameter(o.Name, o.Nickname, o.Description, GH_ParamAccess.item, o.Default));
        }
    }
}
