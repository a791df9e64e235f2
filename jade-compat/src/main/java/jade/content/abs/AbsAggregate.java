package jade.content.abs;

import jade.util.leap.ArrayList;
import jade.util.leap.Iterator;
import jade.util.leap.List;

/** An abstract aggregate, {@code (sequence a b)} or {@code (set a b)}: terms in order. */
public class AbsAggregate extends AbsConcept {
    private static final long serialVersionUID = 1L;
    private final List elements = new ArrayList();
    private AbsTerm elementTemplate;

    /** An empty aggregate of that type ({@code sequence} or {@code set}). */
    public AbsAggregate(String typeName) {
        super(typeName);
    }

    /** Appends an element. */
    public void add(AbsTerm element) {
        elements.add(element);
    }

    /** How many elements it has. */
    public int size() {
        return elements.size();
    }

    /** The element at that index. */
    public AbsTerm get(int i) {
        return (AbsTerm) elements.get(i);
    }

    /** Its elements in order. */
    public Iterator iterator() {
        return elements.iterator();
    }

    /** Removes every element. */
    public void clear() {
        elements.clear();
    }

    /** Whether it holds that element. */
    public boolean contains(AbsTerm element) {
        return elements.contains(element);
    }

    /** The element's index, or -1. */
    public int indexOf(AbsTerm element) {
        return elements.indexOf(element);
    }

    /** Removes and returns the element at that index. */
    public AbsTerm remove(int i) {
        return (AbsTerm) elements.remove(i);
    }

    /** Removes that element. */
    public boolean remove(AbsTerm element) {
        return elements.remove(element);
    }

    /** Whether it has no element. */
    public boolean isEmpty() {
        return elements.isEmpty();
    }

    /** Its elements as an array. */
    public AbsTerm[] toArray() {
        AbsTerm[] out = new AbsTerm[elements.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = get(i);
        }
        return out;
    }

    /** Sets the element at the index the name gives ({@code "0"}, {@code "1"}, ...), as JADE does. */
    @Override
    public void set(String name, AbsTerm value) {
        int i = Integer.parseInt(name);
        while (elements.size() <= i) {
            elements.add(null);
        }
        elements.remove(i);
        elements.add(i, value);
    }

    /** The element at the index the name gives, or null. */
    @Override
    public AbsObject getAbsObject(String name) {
        try {
            int i = Integer.parseInt(name);
            return i >= 0 && i < elements.size() ? get(i) : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /** The element indexes as names: {@code "0"}, {@code "1"}, ... */
    @Override
    public String[] getNames() {
        String[] out = new String[elements.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = Integer.toString(i);
        }
        return out;
    }

    @Override
    public boolean isGrounded() {
        for (int i = 0; i < elements.size(); i++) {
            if (!get(i).isGrounded()) {
                return false;
            }
        }
        return true;
    }

    @Override
    public int getCount() {
        return elements.size();
    }

    @Override
    public int getAbsType() {
        return ABS_AGGREGATE;
    }

    /** The template of its elements (a query's), or null. */
    public AbsTerm getElementTemplate() {
        return elementTemplate;
    }

    /** Sets the template of its elements. */
    public void setElementTemplate(AbsTerm template) {
        this.elementTemplate = template;
    }

    @Override
    public String toString() {
        StringBuilder b = new StringBuilder("(").append(getTypeName());
        for (int i = 0; i < elements.size(); i++) {
            b.append(' ').append(elements.get(i));
        }
        return b.append(')').toString();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof AbsAggregate a && a.getTypeName().equals(getTypeName()) && a.elements.equals(elements);
    }

    @Override
    public int hashCode() {
        return getTypeName().hashCode() * 31 + elements.hashCode();
    }
}
