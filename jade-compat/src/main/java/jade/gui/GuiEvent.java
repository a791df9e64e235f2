package jade.gui;

import java.util.ArrayList;
import java.util.List;

/** An event a user interface hands to a {@link GuiAgent}: a source, a type and parameters. */
public class GuiEvent {
    protected Object source;
    protected int type;
    private final List<Object> parameters = new ArrayList<>();

    public GuiEvent(Object source, int type) {
        this.source = source;
        this.type = type;
    }

    public int getType() {
        return type;
    }

    public Object getSource() {
        return source;
    }

    public void addParameter(Object param) {
        parameters.add(param);
    }

    /** The parameter at this index (from 0). */
    public Object getParameter(int number) {
        return parameters.get(number);
    }

    public jade.util.leap.Iterator getAllParameter() {
        jade.util.leap.ArrayList l = new jade.util.leap.ArrayList();
        for (Object p : parameters) {
            l.add(p);
        }
        return l.iterator();
    }
}
