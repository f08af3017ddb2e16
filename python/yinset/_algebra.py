"""The Boolean algebra's operators, shared by Region and Solid over their native sets."""


class Algebra:
    """A Yin set around a native set ``_set`` (``Region2`` or ``Solid3``), with the operators
    ``& | - ^ ~`` and ``==`` as set equality; operands of another type give NotImplemented."""

    __slots__ = ("_set",)

    @classmethod
    def _wrap(cls, native):
        """An instance of ``cls`` around a native set."""
        obj = cls.__new__(cls)
        obj._set = native
        return obj

    def _operand(self, other):
        """The native set of ``other`` if it is of this type, else None."""
        return other._set if isinstance(other, type(self)) else None

    @property
    def exact(self):
        """True in exact mode."""
        return self._set.exact

    @property
    def bounded(self):
        """True if the closure is compact."""
        return self._set.is_bounded()

    def __and__(self, other):
        """A ∧ B: the interior of the intersection."""
        o = self._operand(other)
        return NotImplemented if o is None else self._wrap(self._set.meet(o))

    def __or__(self, other):
        """A ∨ B: the interior of the closure of the union."""
        o = self._operand(other)
        return NotImplemented if o is None else self._wrap(self._set.join(o))

    def __sub__(self, other):
        """A ∧ B′: the points of A not in the closure of B."""
        o = self._operand(other)
        return NotImplemented if o is None else self._wrap(self._set.difference(o))

    def __xor__(self, other):
        """(A ∧ B′) ∨ (A′ ∧ B)."""
        o = self._operand(other)
        return NotImplemented if o is None else self._wrap(self._set.symmetric_difference(o))

    def __invert__(self):
        """A′: the interior of the complement."""
        return self._wrap(self._set.complement())

    def __eq__(self, other):
        """Set equality (False across modes)."""
        o = self._operand(other)
        return NotImplemented if o is None else self._set.equals(o)

    __hash__ = None

    def __bool__(self):
        """False for the empty set."""
        return not self._set.is_empty()

    def validate(self):
        """Check the boundary with the kernel's validator; raise YinsetError if invalid."""
        self._set.validate()
