import jade.content.AgentAction;

/** The action of selling a book. */
public class Sell implements AgentAction {
    private Book book;

    public Book getBook() {
        return book;
    }

    public void setBook(Book book) {
        this.book = book;
    }
}
