import jade.content.AgentAction;
import jade.content.onto.annotations.Slot;

/** An action written by position: (Move from to). */
public class Move implements AgentAction {
    private String from;
    private String to;

    @Slot(position = 0, mandatory = true)
    public String getFrom() {
        return from;
    }

    public void setFrom(String from) {
        this.from = from;
    }

    @Slot(position = 1)
    public String getTo() {
        return to;
    }

    public void setTo(String to) {
        this.to = to;
    }
}
