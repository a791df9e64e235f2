package jade.content;

import jade.util.leap.ArrayList;
import jade.util.leap.Iterator;

/** Several content elements sent as one content, {@code (a b )} in SL. */
public class ContentElementList implements ContentElement {
    private static final long serialVersionUID = 1L;
    private final ArrayList elements = new ArrayList();

    /** An empty list. */
    public ContentElementList() {
    }

    /** Appends an element. */
    public void add(ContentElement element) {
        elements.add(element);
    }

    /** How many elements it has. */
    public int size() {
        return elements.size();
    }

    /** The element at that index. */
    public ContentElement get(int i) {
        return (ContentElement) elements.get(i);
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
    public boolean contains(ContentElement element) {
        return elements.contains(element);
    }

    /** The element's index, or -1. */
    public int indexOf(ContentElement element) {
        return elements.indexOf(element);
    }

    /** Removes and returns the element at that index. */
    public ContentElement remove(int i) {
        return (ContentElement) elements.remove(i);
    }

    /** Whether it has no element. */
    public boolean isEmpty() {
        return elements.isEmpty();
    }

    /** Its elements as an array. */
    public ContentElement[] toArray() {
        ContentElement[] out = new ContentElement[elements.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = get(i);
        }
        return out;
    }

    @Override
    public String toString() {
        return elements.toString();
    }
}
